#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/output_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace impm
{
  namespace
  {
    namespace fs = std::filesystem;

    /** What a run's record file says (OutputDirectory::record_file). */
    struct Record
    {
      /** Whether the file exists. */
      bool exists = false;
      /** The scene's name and file. */
      std::string name, file;
      /** The entries of the directory the run found and did not write. */
      std::set<std::string> kept;
    };

    /** The record @p record, if readable. */
    Record
    read_record(const fs::path &record)
    {
      Record        result;
      std::ifstream in(record);
      result.exists = in.good();
      std::string line;
      while (std::getline(in, line))
        if (line.rfind("scene = ", 0) == 0)
          result.name = line.substr(8);
        else if (line.rfind("scene file = ", 0) == 0)
          result.file = line.substr(13);
        else if (line.rfind("kept = ", 0) == 0)
          result.kept.insert(line.substr(7));
      return result;
    }

    /** Whether @p name is one of the checkpoint directories. */
    bool
    is_checkpoint_directory(const std::string &name)
    {
      return name == "checkpoint" || name == "checkpoint.tmp" ||
             name == "checkpoint.old" || name == "checkpoint.damaged";
    }

    /** Whether @p name is a strength reduction's trial or link. */
    bool
    is_trial_entry(const std::string &name)
    {
      static const std::regex trial(
        R"(^(trial_\d+|last_stable|first_failed)$)");
      return std::regex_match(name, trial);
    }

    /** A file in checkpoint directory @p directory that a checkpoint does
     *  not hold (empty: none). */
    std::string
    foreign_in_checkpoint(const fs::path &directory)
    {
      static const std::regex checkpoint_file(
        R"(^(grid|grid\.info|grid_fixed\.data|grid_variable\.data|state\.txt|scene\.prm|manifest\.txt)(\.tmp)?$)");
      for (const auto &entry : fs::directory_iterator(directory))
        if (!entry.is_regular_file() ||
            !std::regex_match(entry.path().filename().string(),
                              checkpoint_file))
          return entry.path().string();
      return "";
    }

    /**
     * The entries of @p directory an earlier run of IMPM wrote, by
     * @p record: those with the names IMPM writes (a directory without a
     * record holds none; an entry with such a name that is not the earlier
     * run's is refused: a run would overwrite it); @p foreign gets the
     * others (not the record and the lock).
     */
    std::vector<fs::path>
    earlier_run_entries(const fs::path           &directory,
                        const Record             &record,
                        std::vector<std::string> &foreign)
    {
      std::vector<fs::path> ours;
      for (const auto &entry : fs::directory_iterator(directory))
        {
          const std::string name = entry.path().filename().string();
          if (name == OutputDirectory::record_file ||
              name == OutputDirectory::lock_file)
            continue;
          const bool checkpoint =
            is_checkpoint_directory(name) && entry.is_directory();
          const bool impm_name =
            checkpoint || is_trial_entry(name) ||
            (entry.is_regular_file() && OutputDirectory::is_run_file(name));
          if (!(record.exists && record.kept.count(name) == 0) && impm_name)
            throw InputError(
              "The output directory '" + directory.string() + "' holds '" +
              name +
              "', which no earlier run of IMPM there lists as its own, "
              "and a run would overwrite it: move or remove it first.");
          if (!impm_name)
            {
              foreign.push_back(name);
              continue;
            }
          if (checkpoint)
            if (const std::string file = foreign_in_checkpoint(entry.path());
                !file.empty())
              throw InputError(
                "The output directory '" + directory.string() + "' holds '" +
                file +
                "', which IMPM did not write, in a checkpoint directory "
                "that a run replaces: move it out of there first.");
          ours.push_back(entry.path());
        }
      std::sort(foreign.begin(), foreign.end());
      return ours;
    }

    /** The descriptor of the lock file this process holds, or -1. */
    int lock_descriptor = -1;

    /**
     * Take the lock on @p path's lock file for this process, recording in
     * it who holds it; an InputError naming the holder if another process
     * holds it. Kept until the process ends (the system releases it then,
     * however the process ends).
     */
    void
    take_lock(const std::string &path, const std::string &scene_name)
    {
      if (lock_descriptor >= 0)
        return;
      const std::string file =
        (std::filesystem::path(path) / OutputDirectory::lock_file).string();
      const int descriptor =
        ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (descriptor < 0)
        throw InputError("Cannot open the lock file " + file + ": " +
                         std::strerror(errno) + ".");
      if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
        {
          const int   error = errno;
          std::string holder;
          char        buffer[512];
          const auto  n = ::pread(descriptor, buffer, sizeof(buffer) - 1, 0);
          if (n > 0)
            holder.assign(buffer, static_cast<std::size_t>(n));
          ::close(descriptor);
          if (error != EWOULDBLOCK)
            throw InputError("Cannot lock " + file + ": " +
                             std::strerror(error) + ".");
          holder = collapse_white_space(holder);
          throw InputError(
            "The output directory '" + path + "' is in use by another run (" +
            (holder.empty() ? std::string("just started") : holder) +
            "): wait for it to end, or give this run another 'Output "
            "directory'.");
        }
      char host[256] = "unknown host";
      ::gethostname(host, sizeof(host) - 1);
      host[sizeof(host) - 1] = '\0';
      char              started[64];
      const std::time_t now = std::time(nullptr);
      std::strftime(started,
                    sizeof(started),
                    "%Y-%m-%d %H:%M:%S UTC",
                    std::gmtime(&now));
      const std::string record = "scene '" + scene_name + "', pid " +
                                 std::to_string(::getpid()) + " on " + host +
                                 ", started " + started + "\n";
      if (::ftruncate(descriptor, 0) != 0 ||
          ::pwrite(descriptor, record.data(), record.size(), 0) !=
            static_cast<ssize_t>(record.size()))
        {
          ::close(descriptor);
          throw InputError("Cannot write the lock file " + file + ": " +
                           std::strerror(errno) + ".");
        }
      lock_descriptor = descriptor;
    }
  } // namespace



  void
  OutputDirectory::lock(const std::string &path,
                        const std::string &scene_name,
                        const MPI_Comm     communicator)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0 &&
        std::filesystem::is_directory(path))
      try
        {
          take_lock(path, scene_name);
        }
      catch (const std::exception &exception)
        {
          error = exception.what();
        }
    throw_if_any_failed(error, communicator, false);
  }



  bool
  OutputDirectory::is_run_file(const std::string &file_name)
  {
    static const std::regex run_file(
      R"(^(steps\.csv|newton\.csv|summary\.json|factor_of_safety\.csv|point_history\.csv|impm-run\.txt|points(_\d+(\.\d+)?|_parts)?\.(vtu|pvtu|pvd|h5|xdmf)|rigid_\d+_\d+\.vtu)(\.tmp)?$)");
    return std::regex_match(file_name, run_file);
  }



  void
  OutputDirectory::prepare(const std::string &path,
                           const std::string &scene_name,
                           const std::string &scene_file,
                           const ExistingRun  existing_run,
                           const MPI_Comm     communicator)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) != 0)
      {
        throw_if_any_failed("", communicator, false);
        return;
      }
    std::string error;
    try
      {
        const fs::path  directory(path);
        std::error_code code;
        fs::create_directories(directory, code);
        if (code || !fs::is_directory(directory))
          throw InputError("Cannot create the output directory '" + path +
                           "' ('Output directory')" +
                           (code ? ": " + code.message() : "") + ".");

        const fs::path record_path = directory / record_file;
        const Record   record      = read_record(record_path);
        if (existing_run == ExistingRun::resume)
          {
            if (record.name != scene_name)
              throw InputError("--resume: the output directory '" + path +
                               "' holds " +
                               (record.name.empty() ?
                                  std::string("no run") :
                                  "the run of scene '" + record.name + "'") +
                               ", not of '" + scene_name + "'.");
            // Keep the run's files; only its unfinished writes go.
            for (const auto &entry : fs::directory_iterator(directory))
              {
                const std::string file_name = entry.path().filename().string();
                if (entry.is_regular_file() && is_run_file(file_name) &&
                    record.kept.count(file_name) == 0 && file_name.size() > 4 &&
                    file_name.compare(file_name.size() - 4, 4, ".tmp") == 0)
                  fs::remove(entry.path());
              }
            throw_if_any_failed("", communicator, false);
            return;
          }
        if (record.exists && existing_run == ExistingRun::refuse &&
            !(record.name == scene_name && record.file == scene_file))
          throw InputError(
            "The output directory '" + path + "' holds the run of " +
            (record.name.empty() ?
               std::string("another scene") :
               "scene '" + record.name + "' (" + record.file + ")") +
            ": give this scene its own 'Output directory', or replace "
            "that run with --overwrite (or 'Existing output = "
            "overwrite').");
        // What the earlier run wrote goes; what IMPM did not write stays,
        // and a directory with such entries new to it is taken only with
        // --overwrite.
        std::vector<std::string>    foreign;
        const std::vector<fs::path> earlier =
          earlier_run_entries(directory, record, foreign);
        std::vector<std::string> unknown;
        for (const std::string &name : foreign)
          if (record.kept.count(name) == 0)
            unknown.push_back(name);
        if (!unknown.empty() && existing_run == ExistingRun::refuse)
          throw InputError(
            "The output directory '" + path + "' holds '" + unknown[0] + "'" +
            (unknown.size() > 1 ?
               " and " + std::to_string(unknown.size() - 1) + " other entr" +
                 (unknown.size() > 2 ? "ies" : "y") :
               std::string()) +
            ", which IMPM did not write: give this scene its own 'Output "
            "directory', or write into it with --overwrite (or 'Existing "
            "output = overwrite'), which leaves what IMPM did not write.");
        // No other run may write here from now on.
        take_lock(path, scene_name);
        for (const fs::path &entry : earlier)
          {
            fs::remove_all(entry, code);
            if (code)
              throw InputError("Cannot remove " + entry.string() +
                               " of an earlier run: " + code.message() + ".");
          }
        std::string text =
          "scene = " + scene_name + "\nscene file = " + scene_file + "\n";
        for (const std::string &name : foreign)
          text += "kept = " + name + "\n";
        write_file_atomically(record_path.string(), text);
      }
    catch (const std::exception &exception)
      {
        error = exception.what();
      }
    throw_if_any_failed(error, communicator, false);
  }
} // namespace impm
