#ifndef impm_core_run_h
#define impm_core_run_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace impm
{
  /**
   * @brief Run the scene held by @p prm (already parsed) in dimension
   * @p dim; @p scene_file (an absolute path, or "default scene") is
   * recorded in the output directory. Throws on bad input or on a failed
   * load step, after everything written so far has been closed.
   */
  template <int dim>
  void
  run_scene(dealii::ParameterHandler &prm,
            const std::string        &scene_file,
            const MPI_Comm            communicator);
} // namespace impm

#endif
