#ifndef impm_program_command_line_h
#define impm_program_command_line_h

// The command line's text and the rank an MPI launcher announces, in
// standard C++ only: the launcher (source/main.cc, which links no deal.II)
// prints the usage text, and it and the program (source/program/program.cc)
// print only on the first process.

#include <cstdlib>
#include <initializer_list>

namespace impm
{
  namespace CommandLineText
  {
    /** @brief The text of `impm --help`. */
    inline constexpr const char *usage =
      "Usage: impm [SCENE.prm] [options]\n"
      "\n"
      "Runs an implicit material point analysis of the scene in SCENE.prm\n"
      "(a deal.II parameter file); without SCENE.prm, runs the built-in\n"
      "default scene (prm/column_compaction.prm).\n"
      "\n"
      "Options:\n"
      "  --set \"Subsection/Entry=value\"  override one entry of the scene\n"
      "                                  (repeatable), e.g.\n"
      "                                  --set \"Grid/Number of cells=1, 64\"\n"
      "  --overwrite                     replace the run of another scene in\n"
      "                                  the output directory (its files are\n"
      "                                  removed first)\n"
      "  --resume                        continue the run in the scene's\n"
      "                                  output directory from its newest\n"
      "                                  checkpoint (on any number of\n"
      "                                  processes); the scene must be the\n"
      "                                  one the checkpoint was written from\n"
      "                                  but for the entries doc/running.md\n"
      "                                  lists (load steps, time step, Output,\n"
      "                                  Checkpoint, Testing)\n"
      "  --resume-with-changes           --resume, accepting any changed\n"
      "                                  entry of the scene\n"
      "  --stop-after-step K             stop after K converged load steps\n"
      "                                  (no summary.json is written)\n"
      "  --quiet                         print only errors and the run's\n"
      "                                  final summary (Output/Quiet)\n"
      "  --verbose                       on an error, print deal.II's full\n"
      "                                  report (source file, condition)\n"
      "                                  after the one-line message\n"
      "  --print-parameters              print every parameter with its\n"
      "                                  default and documentation (with the\n"
      "                                  plugins of the scene's Additional\n"
      "                                  shared libraries), and exit\n"
      "  --version                       print IMPM's version, the revision\n"
      "                                  of its source and deal.II's version,\n"
      "                                  and exit\n"
      "  --help                          print this text and exit\n"
      "\n"
      "Run in parallel with: mpirun -np N impm SCENE.prm\n";


    /**
     * @brief The rank an MPI launcher (Open MPI, MPICH, PMIx, Slurm's srun)
     * or a batch system announces to this process in the environment, read
     * before MPI is started; nullptr without a launcher.
     */
    inline const char *
    launcher_rank_variable()
    {
      for (const char *name :
           {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"})
        if (const char *value = std::getenv(name))
          return value;
      return nullptr;
    }

    /**
     * @brief This process's rank as the launcher announces it; 0 without a
     * launcher.
     */
    inline unsigned int
    launcher_rank()
    {
      const char *value = launcher_rank_variable();
      return value == nullptr ?
               0 :
               static_cast<unsigned int>(std::strtoul(value, nullptr, 10));
    }
  } // namespace CommandLineText
} // namespace impm

#endif
