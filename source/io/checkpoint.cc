#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/checkpoint.h>
#include <impm/io/checkpoint_manifest.h>
#include <impm/io/free_space.h>
#include <impm/io/scene_record.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iostream>
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
                        "it (0: never; >= 0). On SIGTERM, SIGINT (Ctrl-C; a "
                        "second one stops at once) or SIGUSR1 a run abandons "
                        "the load step in progress, saves the last converged "
                        "state and stops (exit status 128 + the signal).");
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
    const std::string damaged_name  = "checkpoint.damaged";
    const std::string state_name    = "state.txt";
    const std::string grid_name     = "grid";

    /** Whether @p directory holds a checkpoint (its manifest is written
     *  last). */
    bool
    is_complete(const fs::path &directory)
    {
      return fs::exists(directory / CheckpointManifest::file_name);
    }

    /** Write @p text to @p path; an error naming it if the write or the
     *  close fails. */
    void
    write_checked(const std::string &path, const std::string &text)
    {
      errno = 0;
      std::ofstream out(path);
      out << text;
      out.close();
      if (!out)
        throw std::runtime_error("Writing the checkpoint file " + path +
                                 " failed" + system_reason() + ".");
    }

    /** The total size of the files in @p directory and the largest one's
     *  (zero if it does not exist). */
    std::pair<std::uintmax_t, std::uintmax_t>
    directory_size(const std::string &directory)
    {
      std::uintmax_t  total = 0, largest = 0;
      std::error_code code;
      for (const auto &entry : fs::directory_iterator(directory, code))
        if (entry.is_regular_file(code))
          {
            const std::uintmax_t size = entry.file_size(code);
            if (!code)
              {
                total += size;
                largest = std::max(largest, size);
              }
          }
      return {total, largest};
    }

    /** What a failed write leaves of the checkpoints in @p base. */
    std::string
    kept_or_none(const fs::path &base)
    {
      return is_complete(base / complete_name) ?
               "; the last checkpoint is kept" :
               "; no checkpoint has been written";
    }

    /** The content of @p path; a CollectiveError naming it if unreadable. */
    std::string
    read_text(const std::string &path, const std::string &what)
    {
      std::ifstream     in(path);
      std::stringstream text;
      text << in.rdbuf();
      if (!in)
        throw CollectiveError("Cannot read the checkpoint " + what + " " +
                              path + ".");
      return text.str();
    }
  } // namespace



  Checkpoint::Checkpoint(const std::string &output_directory,
                         const MPI_Comm     communicator)
    : output_directory(output_directory)
    , communicator(communicator)
  {}



  void
  Checkpoint::write(const std::function<void(const std::string &)> &save_grid,
                    const RunState                                 &state,
                    const std::string                              &scene_text,
                    const Size &estimated_size) const
  {
    const bool root =
      dealii::Utilities::MPI::this_mpi_process(communicator) == 0;
    const fs::path base(output_directory);
    run_collectively(communicator, [&]() {
      if (root)
        {
          // The space for a checkpoint as large as the last one with a
          // tenth more (the points may grow), or as the estimate, an upper
          // bound (the first checkpoint).
          const auto [last_bytes, last_largest] =
            directory_size((base / complete_name).string());
          const std::string shortage =
            space_shortage(output_directory,
                           std::max(last_bytes + last_bytes / 10,
                                    estimated_size.total),
                           std::max(last_largest + last_largest / 10,
                                    estimated_size.largest_file),
                           "the checkpoint");
          if (!shortage.empty())
            throw std::runtime_error(shortage + kept_or_none(base) + ".");
          fs::remove_all(base / partial_name);
          fs::create_directories(base / partial_name);
        }
    });
    // deal.II's save is collective and reports its own failures, but not a
    // write cut short at the file-size limit. Whatever fails, no partial
    // checkpoint is left.
    const auto remove_partial = [&]() {
      if (root)
        {
          std::error_code ignored;
          fs::remove_all(base / partial_name, ignored);
        }
    };
    try
      {
        save_grid((base / partial_name / grid_name).string());
      }
    catch (...)
      {
        remove_partial();
        throw;
      }
    run_collectively(communicator, [&]() {
      if (!root)
        return;
      try
        {
          publish(base, state, scene_text);
        }
      catch (...)
        {
          remove_partial();
          throw;
        }
    });
  }



  void
  Checkpoint::publish(const std::filesystem::path &base,
                      const RunState              &state,
                      const std::string           &scene_text) const
  {
    for (const auto &entry : fs::directory_iterator(base / partial_name))
      if (reached_file_size_limit(entry.path().string()))
        {
          const std::string name = entry.path().string();
          throw std::runtime_error(
            "Writing the checkpoint file " + name +
            " failed (File too large: it reached the file-size limit)" +
            kept_or_none(base) + ".");
        }
    // Plain writes: the directory is not published yet, and the manifest
    // syncs every file it names.
    write_checked((base / partial_name / state_name).string(), state.to_text());
    write_checked((base / partial_name / SceneRecord::file_name).string(),
                  scene_text);
    // The manifest last: its presence marks the checkpoint complete.
    CheckpointManifest::write((base / partial_name).string());
    // The previous checkpoint is kept as checkpoint.old: a resume falls
    // back to it if the newest is found damaged.
    if (fs::exists(base / complete_name))
      {
        fs::remove_all(base / previous_name);
        fs::rename(base / complete_name, base / previous_name);
      }
    fs::rename(base / partial_name, base / complete_name);
    sync_file(base.string(), true);
  }



  void
  Checkpoint::select()
  {
    std::string chosen, error;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      try
        {
          const fs::path base(output_directory);
          std::string    damage;
          for (const auto &name : {complete_name, previous_name})
            {
              const fs::path directory = base / name;
              std::string    reason;
              if (is_complete(directory))
                reason = CheckpointManifest::verify(directory.string());
              else if (name == complete_name && fs::exists(directory))
                reason = directory.string() + " has no " +
                         CheckpointManifest::file_name;
              else
                continue;
              if (reason.empty())
                {
                  chosen = directory.string();
                  break;
                }
              damage +=
                (damage.empty() ? "" : "; the previous one too: ") + reason;
            }
          if (chosen.empty() && damage.empty())
            error = "--resume: the output directory '" + output_directory +
                    "' holds no complete checkpoint (set 'Checkpoint/"
                    "Interval' or 'Checkpoint/Wall time limit', or stop "
                    "a run with SIGTERM, to write one).";
          else if (chosen.empty())
            error = "--resume: the checkpoint is damaged: " + damage +
                    " (no complete checkpoint is left; start the run "
                    "afresh with --overwrite).";
          else if (!damage.empty())
            {
              std::cout << "Note: the newest checkpoint is damaged: " << damage
                        << "; resuming from the previous one, " << chosen
                        << " (the damaged one is kept as " << damaged_name
                        << ")." << std::endl;
              fs::remove_all(base / damaged_name);
              fs::rename(base / complete_name, base / damaged_name);
            }
        }
      catch (const std::exception &exception)
        {
          error = "--resume: " + std::string(exception.what());
        }
    throw_if_any_failed(error, communicator, false);
    directory = dealii::Utilities::MPI::broadcast(communicator, chosen, 0);
  }



  std::string
  Checkpoint::grid_file() const
  {
    if (directory.empty())
      throw std::logic_error("Checkpoint: no checkpoint selected.");
    return (fs::path(directory) / grid_name).string();
  }



  RunState
  Checkpoint::read_state() const
  {
    const std::string path =
      (fs::path(grid_file()).parent_path() / state_name).string();
    return RunState::from_text(read_text(path, "state"), path);
  }



  std::string
  Checkpoint::read_scene() const
  {
    return read_text(
      (fs::path(grid_file()).parent_path() / SceneRecord::file_name).string(),
      "scene");
  }
} // namespace impm
