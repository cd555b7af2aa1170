#ifndef impm_io_output_directory_h
#define impm_io_output_directory_h

#include <mpi.h>

#include <string>

namespace impm
{
  /**
   * @brief The output directory of a run, which holds one run only.
   *
   * A run records itself in the file `impm-run.txt` (its scene name and
   * scene file). At the start, a directory that holds the run of another
   * scene is refused, unless the scene's 'Existing output' is 'overwrite'
   * (or the command line says `--overwrite`); a directory that holds an
   * earlier run of the same scene (same name and file) is taken over. In
   * both cases the files the earlier run wrote (`steps.csv`, `newton.csv`,
   * `summary.json`, `points*` point files and series, the `checkpoint*`
   * directories) are removed first,
   * so that old and new results never mix. Leftover `*.tmp` files of an
   * interrupted write are always removed. Files IMPM does not write are
   * left alone.
   */
  class OutputDirectory
  {
  public:
    /** @brief What to do with a directory that holds another scene's run. */
    enum class ExistingRun
    {
      /** Stop with an error naming the other run. */
      refuse,
      /** Remove its files and write this run. */
      overwrite,
      /** Continue the run of the same scene in it (keep its files). */
      resume
    };

    /**
     * @brief Create or take over @p path for the scene @p scene_name read
     * from @p scene_file; collective on @p communicator (rank 0 does the
     * work; a failure is a CollectiveError on all processes).
     */
    static void
    prepare(const std::string &path,
            const std::string &scene_name,
            const std::string &scene_file,
            const ExistingRun  existing_run,
            const MPI_Comm     communicator);

    /** The name of the file that records the run in its directory. */
    static constexpr const char *record_file = "impm-run.txt";

    /**
     * @brief Whether @p file_name (no directory) is a file an IMPM run
     * writes (or its temporary).
     */
    static bool
    is_run_file(const std::string &file_name);
  };
} // namespace impm

#endif
