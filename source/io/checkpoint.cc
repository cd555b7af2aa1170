#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/checkpoint.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace impm
{
  namespace Parameters
  {
    using namespace dealii;


    void
    Checkpoint::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Integer(0),
                        "Save the run's state in the output directory "
                        "(checkpoint/) every this many converged load "
                        "steps, so that 'impm SCENE --resume' can continue "
                        "it (0: never; >= 0). A run also saves and stops on "
                        "SIGTERM or SIGUSR1.");
      prm.declare_entry("Wall time limit",
                        "0",
                        Patterns::Double(0.),
                        "Save and stop after the first load step that ends "
                        "later than this many seconds after the start (for "
                        "batch jobs with a time limit; 0: none; >= 0).");
      prm.leave_subsection();
    }



    void
    Checkpoint::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Checkpoint");
      interval        = prm.get_integer("Interval");
      wall_time_limit = prm.get_double("Wall time limit");
      prm.leave_subsection();
    }
  } // namespace Parameters



  namespace fs = std::filesystem;

  namespace
  {
    const std::string complete_name = "checkpoint";
    const std::string partial_name  = "checkpoint.tmp";
    const std::string previous_name = "checkpoint.old";
    const std::string state_name    = "state.txt";
    const std::string grid_name     = "grid";

    bool
    is_complete(const fs::path &directory)
    {
      return fs::exists(directory / state_name);
    }
  } // namespace



  Checkpoint::Checkpoint(const std::string &output_directory,
                         const MPI_Comm     communicator)
    : output_directory(output_directory)
    , communicator(communicator)
  {}



  void
  Checkpoint::write(const std::function<void(const std::string &)> &save_grid,
                    const RunState                                 &state) const
  {
    const bool root =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    const fs::path base(output_directory);
    run_collectively(communicator, [&]() {
      if (root)
        {
          fs::remove_all(base / partial_name);
          fs::create_directories(base / partial_name);
        }
    });
    // deal.II's save is collective and reports its own failures.
    save_grid((base / partial_name / grid_name).string());
    run_collectively(communicator, [&]() {
      if (!root)
        return;
      // The state last: its presence marks the checkpoint complete.
      write_file_atomically((base / partial_name / state_name).string(),
                            state.to_text());
      if (fs::exists(base / complete_name))
        {
          fs::remove_all(base / previous_name);
          fs::rename(base / complete_name, base / previous_name);
        }
      fs::rename(base / partial_name, base / complete_name);
      fs::remove_all(base / previous_name);
    });
  }



  std::string
  Checkpoint::newest() const
  {
    const fs::path base(output_directory);
    // A run killed between the two renames leaves only the previous one.
    for (const auto &name : {complete_name, previous_name})
      if (is_complete(base / name))
        return (base / name).string();
    return "";
  }



  std::string
  Checkpoint::grid_file() const
  {
    const std::string directory = newest();
    if (directory.empty())
      throw InputError("--resume: the output directory '" + output_directory +
                       "' holds no complete checkpoint (set 'Checkpoint/"
                       "Interval' or 'Checkpoint/Wall time limit', or stop "
                       "a run with SIGTERM, to write one).");
    return (fs::path(directory) / grid_name).string();
  }



  RunState
  Checkpoint::read_state() const
  {
    const std::string path =
      (fs::path(fs::path(grid_file()).parent_path()) / state_name).string();
    std::ifstream     in(path);
    std::stringstream text;
    text << in.rdbuf();
    if (!in)
      throw CollectiveError("Cannot read the checkpoint state " + path + ".");
    return RunState::from_text(text.str(), path);
  }
} // namespace impm
