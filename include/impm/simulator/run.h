#ifndef impm_simulator_run_h
#define impm_simulator_run_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <impm/base/errors.h>
#include <impm/core/load_path.h>
#include <impm/core/parameters.h>
#include <impm/io/checkpoint.h>
#include <impm/postprocess/output_parameters.h>
#include <impm/solver/solver_parameters.h>

#include <cmath>
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
    /** On a resume, accept a scene that differs from the checkpoint's in
     *  entries that may not change (see SceneRecord). */
    bool resume_with_changes = false;
  };

  /**
   * @brief Everything a scene file says, parsed by the module it belongs
   * to: the scene's description (the grid, bodies, rigid bodies, material
   * points and gravity, in core/), how it is solved (solver/), written and
   * tested (postprocess/) and checkpointed (io/). The couplings and effects
   * parse their own subsections when they are created.
   */
  template <int dim>
  struct RunParameters
  {
    /** The scene's description. */
    Parameters::All<dim> scene;
    /** The subsection "Solver". */
    Parameters::Solver solver;
    /** The subsection "Output". */
    Parameters::Output output;
    /** The subsection "Testing". */
    Parameters::Testing testing;
    /** The subsection "Checkpoint". */
    Parameters::Checkpoint checkpoint;
    /** The subsection `Time`. */
    Parameters::Time time;

    /** @brief Read every module's subsections. */
    void
    parse_parameters(dealii::ParameterHandler &prm)
    {
      scene.parse_parameters(prm);
      solver.parse_parameters(prm);
      output.parse_parameters(prm);
      testing.parse_parameters(prm, dim);
      checkpoint.parse_parameters(prm);
      time.parse_parameters(prm);
      // A time step replaces the number of load steps.
      if (time.time_step > 0.)
        solver.n_load_steps = static_cast<unsigned int>(
          std::ceil(time.end_time / time.time_step - 1e-9));
      time.nominal_step = time.end_time / solver.n_load_steps;
      // The integrators' coefficients scale with 1/dt^2: beyond 1e-150
      // to 1e150 s they would round to zero or overflow.
      const double square = time.nominal_step * time.nominal_step;
      if (time.in_time() && !(square > 1e-300 && square < 1e300))
        throw InputError(
          "'Time/End time' = " + number_text(time.end_time) + " in " +
          std::to_string(solver.n_load_steps) + " steps gives a time step of " +
          number_text(time.nominal_step) +
          " s, outside the range of 1e-150 to 1e150 s that double "
          "precision holds the time integration's coefficients in.");
    }
  };

  /**
   * @brief Declare every entry a scene may set: each module declares its
   * own (the scene's description, the solver, the output, the testing, the
   * checkpoints, the couplings and the effects).
   */
  void
  declare_run_parameters(dealii::ParameterHandler &prm);

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
