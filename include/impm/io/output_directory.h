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
   * scene file, and the entries of the directory it found there and did
   * not write: "kept = NAME"). At the start, a directory that holds the
   * run of another scene is refused, unless the scene's 'Existing output'
   * is 'overwrite' (or the command line says `--overwrite`); a directory
   * that holds an earlier run of the same scene (same name and file) is
   * taken over. The entries the earlier run wrote (those with the names
   * IMPM writes, is_run_file(), the `checkpoint*` directories and a
   * strength reduction's trials, that its record does not list as kept)
   * are removed first, so that old and new results never mix. Entries IMPM
   * did not write (in a directory without a record: all) stay: a
   * directory with such an entry that no earlier run kept is refused
   * (naming one) unless 'overwrite' is asked, and then kept and listed; a
   * checkpoint directory holding a file a checkpoint does not is refused
   * always (a run would replace it). A run holds a lock on the directory
   * (lock()), so that two runs never write in it at once.
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

    /**
     * @brief Lock @p path for this run (collective; rank 0 takes an
     * advisory `flock` on the file lock_file in it, which it holds until
     * it exits, and records in it the scene, its process id, host and
     * start time). A run that finds the lock taken stops with an
     * InputError naming the run that holds it. Nothing is done if @p path
     * is not a directory; prepare() takes the lock as well.
     */
    static void
    lock(const std::string &path,
         const std::string &scene_name,
         const MPI_Comm     communicator);

    /** The name of the lock file in an output directory. */
    static constexpr const char *lock_file = "impm.lock";

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
