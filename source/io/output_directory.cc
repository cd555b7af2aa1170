#include <deal.II/base/mpi.h>

#include <impm/base/errors.h>
#include <impm/io/atomic_file.h>
#include <impm/io/output_directory.h>

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
  } // namespace



  bool
  OutputDirectory::is_run_file(const std::string &file_name)
  {
    static const std::regex run_file(
      R"(^(steps\.csv|newton\.csv|summary\.json|impm-run\.txt|points(_\d+(\.\d+)?|_parts)?\.(vtu|pvtu|pvd|h5|xdmf)|rigid_\d+_\d+\.vtu)(\.tmp)?$)");
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
        // Remove the files of an earlier run, its checkpoints (a later
        // --resume must not continue another run) and any leftover
        // temporary.
        for (const char *checkpoint :
             {"checkpoint", "checkpoint.tmp", "checkpoint.old"})
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
