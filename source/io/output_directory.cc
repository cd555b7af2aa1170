#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/output_directory.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace impm
{
  namespace
  {
    /** The scene name and scene file recorded in @p record, if readable. */
    std::pair<std::string, std::string>
    read_record(const std::filesystem::path &record)
    {
      std::ifstream in(record);
      std::string   line, name, file;
      while (std::getline(in, line))
        if (line.rfind("scene = ", 0) == 0)
          name = line.substr(8);
        else if (line.rfind("scene file = ", 0) == 0)
          file = line.substr(13);
      return {name, file};
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
      R"(^(steps\.csv|newton\.csv|summary\.json|factor_of_safety\.csv|impm-run\.txt|points(_\d+(\.\d+)?|_parts)?\.(vtu|pvtu|pvd|h5|xdmf)|rigid_\d+_\d+\.vtu)(\.tmp)?$)");
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
        namespace fs = std::filesystem;
        const fs::path  directory(path);
        std::error_code code;
        fs::create_directories(directory, code);
        if (code || !fs::is_directory(directory))
          throw InputError("Cannot create the output directory '" + path +
                           "' ('Output directory')" +
                           (code ? ": " + code.message() : "") + ".");

        const fs::path record      = directory / record_file;
        bool           earlier_run = fs::exists(record);
        if (!earlier_run)
          for (const auto &file : fs::directory_iterator(directory))
            if (file.path().filename() == "summary.json" ||
                file.path().filename() == "steps.csv")
              earlier_run = true;
        if (existing_run == ExistingRun::resume)
          {
            const auto [name, file] = read_record(record);
            if (name != scene_name)
              throw InputError(
                "--resume: the output directory '" + path + "' holds " +
                (name.empty() ? std::string("no run") :
                                "the run of scene '" + name + "'") +
                ", not of '" + scene_name + "'.");
            // Keep the run's files; only unfinished writes go.
            for (const auto &entry : fs::directory_iterator(directory))
              {
                const std::string file_name = entry.path().filename().string();
                if (entry.is_regular_file() && is_run_file(file_name) &&
                    file_name.size() > 4 &&
                    file_name.compare(file_name.size() - 4, 4, ".tmp") == 0)
                  fs::remove(entry.path());
              }
            throw_if_any_failed("", communicator, false);
            return;
          }
        if (earlier_run)
          {
            const auto [name, file] = read_record(record);
            const bool same =
              fs::exists(record) && name == scene_name && file == scene_file;
            if (!same && existing_run == ExistingRun::refuse)
              throw InputError(
                "The output directory '" + path + "' holds the run of " +
                (name.empty() ? std::string("another scene") :
                                "scene '" + name + "' (" + file + ")") +
                ": give this scene its own 'Output directory', or replace "
                "that run with --overwrite (or 'Existing output = "
                "overwrite').");
          }
        // No other run may write here from now on.
        take_lock(path, scene_name);
        // Remove the files of an earlier run, its checkpoints (a later
        // --resume must not continue another run) and any leftover
        // temporary.
        for (const char *checkpoint : {"checkpoint",
                                       "checkpoint.tmp",
                                       "checkpoint.old",
                                       "checkpoint.damaged"})
          fs::remove_all(directory / checkpoint);
        for (const auto &file : fs::directory_iterator(directory))
          {
            const std::string file_name = file.path().filename().string();
            if (file.is_regular_file() && is_run_file(file_name))
              {
                fs::remove(file.path(), code);
                if (code)
                  throw InputError("Cannot remove " + file.path().string() +
                                   " of an earlier run: " + code.message() +
                                   ".");
              }
          }
        write_file_atomically(record.string(),
                              "scene = " + scene_name +
                                "\nscene file = " + scene_file + "\n");
      }
    catch (const std::exception &exception)
      {
        error = exception.what();
      }
    throw_if_any_failed(error, communicator, false);
  }
} // namespace impm
