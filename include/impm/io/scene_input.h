#ifndef impm_io_scene_input_h
#define impm_io_scene_input_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief Reading a scene into a ParameterHandler whose entries are all
   * declared, with every mistake reported as one InputError line: the file
   * and line, the entry with its subsection path, the value and, in words,
   * what the entry allows. deal.II's parser does the reading; its
   * exceptions are translated here.
   */
  namespace SceneInput
  {
    /**
     * @brief Parse the scene file @p file_name into @p prm. A file that
     * cannot be read, that sets no entry, or that the parser rejects is an
     * InputError. A UTF-8 byte-order mark at the start is skipped.
     */
    void
    parse_file(dealii::ParameterHandler &prm, const std::string &file_name);

    /**
     * @brief Parse the scene held in @p text, named @p name in messages.
     */
    void
    parse_text(dealii::ParameterHandler &prm,
               const std::string        &text,
               const std::string        &name);

    /**
     * @brief Apply the command-line overrides "Subsection/.../Entry=value"
     * in their order; an unknown entry or a value its pattern rejects is an
     * InputError naming the override.
     */
    void
    apply_overrides(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &assignments);

    /**
     * @brief Check every numeric entry (a number or a list of numbers) of
     * @p prm, once the scene and the overrides are read: each number must be
     * finite and representable (not a subnormal that would lose its digits).
     * deal.II's patterns accept both; the error names the entry and the value.
     */
    void
    check_numbers(const dealii::ParameterHandler &prm);

    /**
     * @brief Make the file names the scene gives (the rigid bodies' 'STL
     * file') that are relative paths relative to the directory of @p
     * scene_file, where they were written, instead of the working
     * directory; with no scene file (the default scene) they stay as they
     * are.
     */
    void
    resolve_paths(dealii::ParameterHandler &prm, const std::string &scene_file);

    /**
     * @brief A deal.II pattern description ("[Double 0...MAX_DOUBLE
     * (inclusive)]") in words ("a number >= 0").
     */
    std::string
    describe_pattern(const std::string &description);
  } // namespace SceneInput
} // namespace impm

#endif
