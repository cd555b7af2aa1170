#ifndef impm_base_plugin_list_h
#define impm_base_plugin_list_h

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace impm
{
  /**
   * @brief The mistakes found while plugins registered (a name registered
   * twice in one list), one line each. Registration runs in static
   * initialisers, while the program starts or a plugin library is loaded,
   * where an exception cannot be reported; the list is checked afterwards
   * (SharedLibraries::check_registrations()).
   */
  std::vector<std::string> &
  plugin_registration_errors();

  /**
   * @brief A list of interchangeable plugins registered by name (ASPECT's
   * `PluginList` pattern), one list per interface: materials, force effects,
   * postprocessors.
   *
   * Each plugin registers, from a static initialiser in its own translation
   * unit, its name, a one-line description, a function that declares its
   * parameters (inside a subsection the caller enters) and a function that
   * creates it. The registration order of plugins in different translation
   * units is unspecified; the list keeps them sorted by name so that every
   * run, on every process, sees the same order.
   *
   * @tparam Interface The base class of the plugins.
   * @tparam CreateArguments What the creating function is given.
   */
  template <typename Interface, typename... CreateArguments>
  class PluginList
  {
  public:
    /** @brief One registered plugin. */
    struct Entry
    {
      /** Name used in scenes (and as the name of its subsection). */
      std::string name;
      /** One line of documentation. */
      std::string description;
      /** Declares its parameters; may be empty. */
      std::function<void(dealii::ParameterHandler &)> declare_parameters;
      /** Creates it; may return nullptr when the scene does not use it. */
      std::function<std::unique_ptr<Interface>(CreateArguments...)> create;
    };

    /**
     * @brief Register a plugin; returns true so that it can initialise a
     * static variable. A second plugin of the same name is not registered:
     * the mistake is added to plugin_registration_errors() and the result
     * is false.
     */
    static bool
    register_plugin(const Entry &entry)
    {
      auto &list = storage();
      for (const Entry &other : list)
        if (other.name == entry.name)
          {
            plugin_registration_errors().push_back(
              "two plugins are registered as '" + entry.name + "'");
            return false;
          }
      auto position = list.begin();
      while (position != list.end() && position->name < entry.name)
        ++position;
      list.insert(position, entry);
      return true;
    }

    /** @brief All registered plugins, sorted by name. */
    static const std::vector<Entry> &
    entries()
    {
      return storage();
    }

    /** @brief The names joined by '|', for `Patterns::Selection`. */
    static std::string
    names()
    {
      std::string joined;
      for (const Entry &entry : storage())
        joined += (joined.empty() ? "" : "|") + entry.name;
      return joined;
    }

    /**
     * @brief The plugin called @p name; an unknown name is an error that
     * lists the known ones.
     */
    static const Entry &
    find(const std::string &name)
    {
      for (const Entry &entry : storage())
        if (entry.name == name)
          return entry;
      throw std::invalid_argument("'" + name +
                                  "' is not a known name; known: " + names());
    }

  private:
    /** The list, created on first use (safe during static initialisation). */
    static std::vector<Entry> &
    storage()
    {
      static std::vector<Entry> list;
      return list;
    }
  };
} // namespace impm

/**
 * Register the plugin @p CLASS (a template over dim) in the registry
 * LIST<dim> (a PluginList) as @p NAME, for dim = 2 and 3, when the library
 * is loaded. @p DECLARE and @p CREATE are the entry's parameter declaration
 * and factory, expressions that may use dim (a lambda in parentheses).
 */
#define IMPM_REGISTER_PLUGIN_IN_BOTH_DIMENSIONS(                        \
  LIST, CLASS, NAME, DECLARE, CREATE)                                   \
  namespace                                                             \
  {                                                                     \
    template <int dim>                                                  \
    bool register_##CLASS()                                             \
    {                                                                   \
      return LIST<dim>::register_plugin({NAME, NAME, DECLARE, CREATE}); \
    }                                                                   \
    const bool CLASS##_registered =                                     \
      register_##CLASS<2>() && register_##CLASS<3>();                   \
  }

#endif
