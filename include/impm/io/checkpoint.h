#ifndef impm_io_checkpoint_h
#define impm_io_checkpoint_h

#include <deal.II/base/parameter_handler.h>

#include <impm/io/run_state.h>

#include <mpi.h>

#include <cstdint>
#include <filesystem>
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
   * distributed triangulation with the particle handler's data), the
   * replicated state (`state.txt`, a RunState), the scene it was written
   * from (`scene.prm`, see SceneRecord) and, written last, the manifest of
   * these files with their sizes and checksums (`manifest.txt`, see
   * CheckpointManifest). It is written as `checkpoint.tmp/` and takes the
   * name `checkpoint/` only when complete; the previous checkpoint is kept
   * as `checkpoint.old/`, so that a run killed at any moment leaves a
   * complete checkpoint if it ever wrote one, and a resume can fall back to
   * the previous checkpoint when the newest does not match its manifest.
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

    /** @brief The size of a checkpoint, in bytes. */
    struct Size
    {
      /** All its files together, on all processes. */
      std::uintmax_t total;
      /** Its largest file (the points' data). */
      std::uintmax_t largest_file;
    };

    /**
     * @brief Write a checkpoint (collective): @p save_grid saves the grid
     * and the points under the file name it is given, on every process;
     * rank 0 writes @p state, the scene @p scene_text (from
     * SceneRecord::to_text()) and the manifest, and puts the checkpoint in
     * place. Before anything is written, the free space is checked against
     * the larger of @p estimated_size and the last checkpoint's sizes with
     * a tenth more: a full disk met inside the grid's save (p4est's MPI-IO)
     * aborts instead of reporting. A failure leaves no partial directory.
     *
     * @param save_grid Saves the grid and the points (collective).
     * @param state The run's state, written as `state.txt`.
     * @param scene_text The scene, written as `scene.prm`.
     * @param estimated_size An upper bound of the checkpoint's size (the
     *   points' serialized data and the cells').
     */
    void
    write(const std::function<void(const std::string &)> &save_grid,
          const RunState                                 &state,
          const std::string                              &scene_text,
          const Size                                     &estimated_size) const;

    /**
     * @brief Choose the checkpoint to resume from (collective; to be
     * called before anything of it is read): rank 0 verifies the newest
     * against its manifest and, if it is damaged, the previous one, which
     * it then takes (saying so in one line, and keeping the damaged one as
     * `checkpoint.damaged/`). A CollectiveError naming the damaged file if
     * no checkpoint verifies, an error if there is none.
     */
    void
    select();

    /** @brief The grid file name of the selected checkpoint. */
    std::string
    grid_file() const;

    /** @brief The state of the selected checkpoint. */
    RunState
    read_state() const;

    /** @brief The scene the selected checkpoint was written from (a
     *  parameter file, see SceneRecord). */
    std::string
    read_scene() const;

  private:
    /** Rank 0: after the grid's save into `checkpoint.tmp/` under @p base,
     *  check its files against the file-size limit, write the state, the
     *  scene and the manifest, and publish it as `checkpoint/` (the last
     *  one kept as `checkpoint.old/`). */
    void
    publish(const std::filesystem::path &base,
            const RunState              &state,
            const std::string           &scene_text) const;

    const std::string output_directory;
    const MPI_Comm    communicator;
    /** The directory of the selected checkpoint ("" before select()). */
    std::string directory;
  };
} // namespace impm

#endif
