#ifndef impm_io_scene_record_h
#define impm_io_scene_record_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief The scene a checkpoint was written from, kept in it as a
   * parameter file (`scene.prm`: every entry with its value, as deal.II
   * prints it), and its comparison with the scene of a resumed run.
   *
   * A resumed run must compute with the scene that wrote the checkpoint;
   * only the entries that change what is written or how far the run goes
   * may differ (may_change_on_resume()).
   */
  namespace SceneRecord
  {
    /** The name of the scene's file in a checkpoint directory. */
    constexpr const char *file_name = "scene.prm";

    /**
     * @brief Every entry of @p prm with its value, as a parameter file
     * (deal.II's short PRM format).
     */
    std::string
    to_text(const dealii::ParameterHandler &prm);

    /**
     * @brief Whether the entry @p path ("Subsection/Entry") may differ
     * between a checkpoint and the run resumed from it: the number of load
     * steps and the end time (a run may be extended), the subsections
     * "Output", "Checkpoint" and "Testing" (what is written, printed and
     * checked, not what is computed), and 'Existing output' and 'Output
     * directory' (where the run lives).
     */
    bool
    may_change_on_resume(const std::string &path);

    /**
     * @brief The entries in which the scene @p current differs from
     * @p saved (both from to_text()), those that may change on a resume
     * left out; each as "'Path' CHECKPOINT -> NOW".
     */
    std::vector<std::string>
    differences(const std::string &saved, const std::string &current);
  } // namespace SceneRecord
} // namespace impm

#endif
