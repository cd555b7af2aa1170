#ifndef impm_simulator_run_h
#define impm_simulator_run_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace impm
{
  /**
   * @brief How main() asks for a scene to be run, beyond the scene itself.
   */
  struct RunOptions
  {
    /** The scene file as an absolute path, or "default scene"; recorded
     *  in the output directory. */
    std::string scene_file = "default scene";
    /** Stop after this many converged load steps (0: never). */
    unsigned int stop_after_step = 0;
    /** Continue from the newest checkpoint in the output directory. */
    bool resume = false;
  };

  /**
   * @brief Run the scene held by @p prm (already parsed) in dimension
   * @p dim, as @p options ask. Throws on bad input or on a failed
   * load step, after everything written so far has been closed.
   */
  template <int dim>
  void
  run_scene(dealii::ParameterHandler &prm,
            const RunOptions         &options,
            const MPI_Comm            communicator);
} // namespace impm

#endif
