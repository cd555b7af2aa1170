#ifndef impm_io_shared_libraries_h
#define impm_io_shared_libraries_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief Plugins from shared libraries: the scene's top-level entry
   * `Additional shared libraries` names libraries (built against an
   * installed IMPM, `find_package(impm)`) whose materials, effects,
   * couplings and postprocessors register themselves when the library is
   * loaded.
   *
   * The libraries must be loaded before the scene's entries are declared,
   * because the names of the registered plugins are the entries' choices
   * (`Patterns::Selection`). main() therefore finds the entry by a light
   * scan of the scene file and of the `--set` overrides (libraries_named()),
   * loads the libraries on every process (load()), and only then declares
   * and reads the scene as usual, where the entry is declared again
   * (declare_parameters()) so that the scene may set it.
   */
  namespace SharedLibraries
  {
    /** @brief The entry's name, at the scene's top level. */
    inline const std::string entry = "Additional shared libraries";

    /**
     * @brief Declare `Additional shared libraries` at the top level of
     * @p prm.
     */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The libraries the scene names: the value of the top-level
     * entry in @p scene_file (the last `set` of it outside any subsection;
     * no file if empty, an unreadable file names none: reading it later
     * reports the error), replaced by the last override of @p overrides
     * that sets it. A relative path with a '/' is taken relative to the
     * scene file's directory when the file names it, to the working
     * directory when an override does; a name without '/' is left to the
     * system's search (LD_LIBRARY_PATH, the system's directories).
     */
    std::vector<std::string>
    libraries_named(const std::string              &scene_file,
                    const std::vector<std::string> &overrides);

    /**
     * @brief Check, once the scene is read into @p prm, that the entry
     * holds what libraries_named() found in @p scene_file and
     * @p overrides: a value set elsewhere (in a file the scene includes)
     * came too late to be loaded, an InputError.
     */
    void
    check_read(const dealii::ParameterHandler &prm,
               const std::string              &scene_file,
               const std::vector<std::string> &overrides);

    /**
     * @brief The libraries named by the value @p value of the entry (a
     * comma-separated list), relative paths with a '/' resolved against
     * @p directory (none if empty).
     */
    std::vector<std::string>
    split_value(const std::string &value, const std::string &directory);

    /**
     * @brief Load each library of @p libraries (dlopen, all symbols
     * resolved at once, visible to the libraries loaded later) in the
     * order given, and check what their plugins registered.
     * @return "" if all loaded, else one line naming the library and the
     *   system's reason (dlerror), or the plugin registered twice.
     */
    std::string
    load(const std::vector<std::string> &libraries);

    /**
     * @brief The mistakes of the plugins registered so far (a name
     * registered twice) as one line naming @p where they came from ("" if
     * none); each mistake is reported once.
     */
    std::string
    check_registrations(const std::string &where);
  } // namespace SharedLibraries
} // namespace impm

#endif
