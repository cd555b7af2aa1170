// run_scene: a scene's checks, then one run of MPMSolver (from a checkpoint
// with --resume, which is verified and compared with the scene first) or a
// strength reduction.
#include <impm/base/errors.h>
#include <impm/core/scene_checks.h>
#include <impm/io/checkpoint.h>
#include <impm/io/output_directory.h>
#include <impm/io/scene_record.h>
#include <impm/postprocess/column_solution.h>
#include <impm/simulator/mpm_solver.h>
#include <impm/simulator/run.h>
#include <impm/simulator/strength_reduction.h>

#include <string>
#include <vector>

namespace impm
{
  template <int dim>
  void
  run_scene(ParameterHandler &prm,
            const RunOptions &options,
            const MPI_Comm    communicator)
  {
    RunParameters<dim> settings;
    settings.parse_parameters(prm);
    Parameters::All<dim> &parameters = settings.scene;
    parameters.scene.file            = options.scene_file;
    parameters.scene.stop_after_step = options.stop_after_step;
    SceneChecks::check(parameters, communicator);
    SceneChecks::check_motion_start(parameters, settings.time);
    if (settings.output.analytical_solution ==
        Parameters::AnalyticalSolution::column)
      ColumnSolution<dim>::check_scene(parameters);
    if (StrengthReduction<dim>::enabled(prm))
      {
        StrengthReduction<dim>::run(prm, options, communicator);
        return;
      }
    if (!options.resume)
      {
        MPMSolver<dim> solver(settings,
                              prm,
                              EffectRegistry::create_enabled<dim>(prm),
                              communicator);
        solver.run();
        return;
      }
    // No other run may write the checkpoint while it is read.
    OutputDirectory::lock(parameters.scene.output_directory,
                          parameters.scene.name,
                          communicator);
    Checkpoint checkpoint(parameters.scene.output_directory, communicator);
    checkpoint.select();
    const std::string grid_file = checkpoint.grid_file();
    const RunState    state     = checkpoint.read_state();
    if (state.get_string("scene.name") != parameters.scene.name)
      throw InputError("--resume: the checkpoint in '" +
                       parameters.scene.output_directory + "' is of scene '" +
                       state.get_string("scene.name") + "', not '" +
                       parameters.scene.name + "'.");
    if (!options.resume_with_changes)
      {
        const std::vector<std::string> differences =
          SceneRecord::differences(checkpoint.read_scene(),
                                   SceneRecord::to_text(prm));
        std::string list;
        for (const auto &difference : differences)
          list += (list.empty() ? "" : "; ") + difference;
        if (!differences.empty())
          throw InputError(
            "--resume: the scene differs from the one the checkpoint was "
            "written from in " +
            std::to_string(differences.size()) + " entr" +
            (differences.size() == 1 ? "y" : "ies") + ": " + list +
            " (resume with that scene, or give --resume-with-changes).");
      }
    MPMSolver<dim> solver(settings,
                          prm,
                          EffectRegistry::create_enabled<dim>(prm),
                          communicator,
                          &state,
                          grid_file);
    solver.run();
  }



  template void
  run_scene<2>(ParameterHandler &, const RunOptions &, const MPI_Comm);
  template void
  run_scene<3>(ParameterHandler &, const RunOptions &, const MPI_Comm);
} // namespace impm
