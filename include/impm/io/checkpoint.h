#ifndef impm_io_checkpoint_h
#define impm_io_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <impm/io/run_state.h>

#include <mpi.h>

#include <functional>
#include <string>

namespace impm
{
  namespace Parameters
  {
    /** @brief When the run saves its state (subsection "Checkpoint"). */
    struct Checkpoint
    {
      /** Save every this many converged load steps (0: never). */
      unsigned int interval = 0;
      /** Save and stop once the run has taken this many seconds of wall
       *  time (0: no limit). */
      double wall_time_limit = 0.;

      /** @brief Declare the entries in subsection "Checkpoint". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);
      /** @brief Read them. */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };
  } // namespace Parameters

  /**
   * @brief The checkpoints of a run in its output directory.
   *
   * A checkpoint is the directory `checkpoint/` in the output directory: the
   * grid with the points attached (`grid*`, deal.II's serialization of the
   * distributed triangulation with the particle handler's data) and the
   * replicated state (`state.txt`, a RunState). It is written as
   * `checkpoint.tmp/` and takes the name `checkpoint/` only when complete;
   * the previous checkpoint is kept (as `checkpoint.old/` during the swap)
   * until then, so that a run killed at any moment leaves a complete
   * checkpoint if it ever wrote one.
   */
  class Checkpoint
  {
  public:
    /**
     * @brief The checkpoints in @p output_directory, shared by the
     * processes of @p communicator.
     */
    Checkpoint(const std::string &output_directory,
               const MPI_Comm     communicator);

    /**
     * @brief Write a checkpoint (collective): @p save_grid saves the grid
     * and the points under the file name it is given, on every process;
     * rank 0 writes @p state and puts the checkpoint in place.
     */
    void
    write(const std::function<void(const std::string &)> &save_grid,
          const RunState                                 &state) const;

    /**
     * @brief The grid file name of the newest complete checkpoint; an
     * InputError if there is none.
     */
    std::string
    grid_file() const;

    /** @brief The state of the newest complete checkpoint. */
    RunState
    read_state() const;

  private:
    /** The directory of the newest complete checkpoint, or "". */
    std::string
    newest() const;

    const std::string output_directory;
    const MPI_Comm    communicator;
  };
} // namespace impm

#endif
