#ifndef impm_core_run_h
#define impm_core_run_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

namespace impm
{
  /**
   * @brief Run the scene held by @p prm (already parsed) in dimension
   * @p dim. Throws on bad input or on a failed load step, after everything
   * written so far has been closed.
   */
  template <int dim>
  void
  run_scene(dealii::ParameterHandler &prm, const MPI_Comm communicator);
} // namespace impm

#endif
