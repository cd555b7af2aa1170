// The program: the command line read, the scene parsed and run (what
// build/impm [scene.prm] [--set "Subsection/Entry=value"]... does, called by
// the thin launcher source/main.cc once it has loaded this library).

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/stop_signal.h>
#include <impm/core/default_scene.h>
#include <impm/core/parameters.h>
#include <impm/io/scene_input.h>
#include <impm/io/shared_libraries.h>
#include <impm/program/command_line_text.h>
#include <impm/program/program.h>
#include <impm/simulator/material_test.h>
#include <impm/simulator/run.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace
{



  /** @brief What the command line asks for. */
  struct CommandLine
  {
    /** The scene file; empty for the default scene. */
    std::string scene_file;
    /** The `--set` assignments (and --overwrite's, --quiet's), in order. */
    std::vector<std::string> overrides;
    /** How the scene is run. */
    impm::RunOptions options;
    /** --print-parameters. */
    bool print_parameters = false;
  };



  /**
   * @brief Read the command line (but --verbose; the launcher answers --help). A mistake is an
   * InputError.
   */
  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    CommandLine command_line;
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        if (argument == "--verbose")
          continue;
        else if (argument == "--stop-after-step")
          {
            const std::string value = i + 1 < argc ? argv[++i] : "";
            char             *end   = nullptr;
            const long        steps = std::strtol(value.c_str(), &end, 10);
            if (value.empty() || *end != '\0' || steps < 1 ||
                steps > 1000000000)
              throw impm::InputError("--stop-after-step '" + value +
                                     "': expected a number of load steps "
                                     "from 1 to 1e9.");
            command_line.options.stop_after_step =
              static_cast<unsigned int>(steps);
          }
        else if (argument == "--resume")
          command_line.options.resume = true;
        else if (argument == "--resume-with-changes")
          command_line.options.resume =
            command_line.options.resume_with_changes = true;
        else if (argument == "--overwrite")
          command_line.overrides.push_back("Existing output=overwrite");
        else if (argument == "--quiet")
          command_line.overrides.push_back("Output/Quiet=true");
        else if (argument == "--print-parameters")
          command_line.print_parameters = true;
        else if (argument == "--set")
          {
            if (i + 1 >= argc)
              throw impm::InputError("--set needs an argument "
                                     "\"Subsection/Entry=value\".");
            command_line.overrides.push_back(argv[++i]);
          }
        else if (argument.rfind("--", 0) == 0)
          throw impm::InputError("Unknown option '" + argument +
                                 "'; see impm --help.");
        else if (command_line.scene_file.empty())
          command_line.scene_file = argument;
        else
          throw impm::InputError("Only one scene file may be given; got '" +
                                 command_line.scene_file + "' and '" +
                                 argument + "'.");
      }
    return command_line;
  }



  /**
   * @brief What needs no MPI: --print-parameters (with the plugin libraries
   * the scene names loaded; the launcher answers --help). Started under
   * mpirun, only the first process prints.
   * @return The exit status.
   */
  int
  print_parameters(const int argc, char **argv, const bool verbose)
  {
    const bool is_root = impm::CommandLineText::launcher_rank() == 0;
    try
      {
        const CommandLine command_line = parse_command_line(argc, argv);
        const std::string error        = impm::SharedLibraries::load(
          impm::SharedLibraries::libraries_named(command_line.scene_file,
                                                 command_line.overrides));
        if (!error.empty())
          throw impm::InputError(error);
        dealii::ParameterHandler prm;
        impm::declare_run_parameters(prm);
        if (is_root)
          prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
        return 0;
      }
    catch (const std::exception &exception)
      {
        if (is_root)
          {
            std::cerr << "Error: " << impm::one_line_message(exception)
                      << std::endl;
            if (verbose)
              std::cerr << exception.what() << std::endl;
          }
        return 1;
      }
  }

} // namespace

int
impm_program_main(int argc, char **argv)
{
  // First: a SIGTERM, SIGINT or SIGUSR1 at any later moment is noted, and
  // the run saves its last converged state and stops (StopSignal).
  impm::StopSignal::install();
  // Open MPI's shared-file-pointer component 'sm' guards an MPI-IO file with
  // a named semaphore in /dev/shm named after the file's base name
  // (sem.OMPIO_grid for the checkpoint's grid): a run killed while it holds
  // it (SIGKILL during a checkpoint) leaves it taken, and every later run on
  // the machine then waits forever in its first checkpoint. IMPM uses no
  // shared file pointer; without 'sm' Open MPI takes a component whose locks
  // die with the process. A user's own choice (the variable set) is kept.
  setenv("OMPI_MCA_sharedfp", "^sm", 0);
  // A run without a launcher (no mpirun) is one process: Open MPI's singleton
  // start then need not start a runtime daemon nor probe the network's
  // transports, which halves its start (0.62 s to 0.30 s on this machine,
  // measured on a scene refused at its first line). A user's own choice is
  // kept here too.
  if (impm::CommandLineText::launcher_rank_variable() == nullptr)
    {
      setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
      setenv("OMPI_MCA_pml", "ob1", 0);
    }
  // Errors are reported by their message; a user needs no stack trace.
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  // A file-size limit (ulimit -f) makes a write fail with an error the
  // program reports, instead of killing it with SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  bool verbose = false, parameters_only = false;
  for (int i = 1; i < argc; ++i)
    {
      const std::string argument = argv[i];
      verbose                    = verbose || argument == "--verbose";
      parameters_only = parameters_only || argument == "--print-parameters";
    }
  // Starting MPI takes longer than printing a text.
  if (parameters_only)
    return print_parameters(argc, argv, verbose);

  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // Again: deal.II starts PETSc, whose PetscPopSignalHandler() sets SIGTERM
  // (with SIGSEGV, SIGBUS, SIGFPE) back to the default.
  impm::StopSignal::install();
  // The launcher blocked the stop signals while it loaded the libraries;
  // from here they are noted (one that came meanwhile is delivered now).
  impm::StopSignal::unblock();
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const bool is_root = rank == 0;
  try
    {
      CommandLine        command_line = parse_command_line(argc, argv);
      const std::string &scene_file   = command_line.scene_file;
      impm::RunOptions  &options      = command_line.options;
      // The plugins' libraries are loaded on every process before the
      // entries are declared: their names are the entries' choices.
      impm::throw_if_any_failed(impm::SharedLibraries::load(
                                  impm::SharedLibraries::libraries_named(
                                    scene_file, command_line.overrides)),
                                MPI_COMM_WORLD,
                                false);

      dealii::ParameterHandler prm;
      impm::declare_run_parameters(prm);
      if (scene_file.empty())
        impm::SceneInput::parse_text(prm, impm::default_scene, "default scene");
      else
        impm::SceneInput::parse_file(prm, scene_file);
      impm::SceneInput::apply_overrides(prm, command_line.overrides);
      impm::SharedLibraries::check_read(prm,
                                        scene_file,
                                        command_line.overrides);
      impm::SceneInput::check_numbers(prm);
      impm::SceneInput::resolve_paths(prm, scene_file);

      if (!scene_file.empty())
        options.scene_file =
          std::filesystem::absolute(scene_file).lexically_normal().string();
      // A material test drives one point of Body 1's material and runs no
      // scene: the root process alone.
      if (impm::MaterialTest::enabled(prm))
        {
          if (is_root)
            impm::MaterialTest::run(prm, std::cout);
          return 0;
        }
      if (prm.get_integer("Dimension") == 2)
        impm::run_scene<2>(prm, options, MPI_COMM_WORLD);
      else
        impm::run_scene<3>(prm, options, MPI_COMM_WORLD);
    }
  catch (const impm::StoppedBySignal &stop)
    {
      if (is_root)
        std::cerr << stop.what() << std::endl;
      return impm::StopSignal::exit_status(stop.signal);
    }
  catch (const std::exception &exception)
    {
      // An error all processes raise together is printed once; one raised
      // by this process alone stops the others, which may be waiting for
      // it in a collective operation.
      const bool collective =
        dynamic_cast<const impm::CollectiveError *>(&exception) != nullptr ||
        dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1;
      if (collective && !is_root)
        return 1;
      std::cerr << "Error: "
                << (collective ? "" : "process " + std::to_string(rank) + ": ")
                << impm::one_line_message(exception) << std::endl;
      if (verbose)
        std::cerr << exception.what() << std::endl;
      if (!collective)
        MPI_Abort(MPI_COMM_WORLD, 1);
      return 1;
    }
  catch (...)
    {
      std::cerr << "Error: process " << rank << ": unknown exception."
                << std::endl;
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  return 0;
}
