#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/plugin_list.h>
#include <impm/io/shared_libraries.h>

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace impm
{
  namespace SharedLibraries
  {
    namespace
    {
      /** The first word of @p line in lower case. */
      std::string
      keyword_of(const std::string &line)
      {
        std::string keyword =
          line.substr(0, std::min(line.find_first_of(" \t"), line.size()));
        std::transform(keyword.begin(),
                       keyword.end(),
                       keyword.begin(),
                       [](const unsigned char c) { return std::tolower(c); });
        return keyword;
      }

      /**
       * The value of the last top-level `set Additional shared libraries`
       * of the scene @p text, as deal.II's parser reads it (comments
       * removed, a line ending in a backslash joined with the next), and
       * whether there is one.
       */
      std::pair<bool, std::string>
      value_in_scene(const std::string &text)
      {
        std::istringstream           in(text);
        std::string                  line, joined;
        unsigned int                 depth = 0;
        std::pair<bool, std::string> found(false, "");
        while (std::getline(in, line))
          {
            for (std::size_t i = 0; i < line.size(); ++i)
              if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
                {
                  line.erase(i);
                  break;
                }
            while (!line.empty() &&
                   std::isspace(static_cast<unsigned char>(line.back())))
              line.pop_back();
            if (!line.empty() && line.back() == '\\')
              {
                line.pop_back();
                joined += line;
                continue;
              }
            const std::string words = dealii::Utilities::trim(joined + line);
            joined.clear();
            const std::string keyword = keyword_of(words);
            if (keyword == "subsection")
              ++depth;
            else if (keyword == "end" && depth > 0)
              --depth;
            else if (keyword == "set" && depth == 0)
              {
                const auto equals = words.find('=');
                if (equals == std::string::npos)
                  continue;
                if (collapse_white_space(words.substr(3, equals - 3)) == entry)
                  found = {true, words.substr(equals + 1)};
              }
          }
        return found;
      }
    } // namespace



    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry(
        entry,
        "",
        dealii::Patterns::Anything(),
        "Shared libraries to load before the scene is read, a "
        "comma-separated list of paths: plugins (materials, effects, "
        "couplings, postprocessors) built against an installed IMPM with "
        "find_package(impm), which register themselves when loaded, so "
        "that the scene may name them (doc/plugins.md). A relative path "
        "with a '/' is relative to the scene file's directory (to the "
        "working directory when given by --set); a name without '/' is "
        "looked up as the system looks up libraries (LD_LIBRARY_PATH). "
        "Only this top-level entry of the scene file itself or --set is "
        "read for it (not a file the scene includes).");
    }



    std::vector<std::string>
    split_value(const std::string &value, const std::string &directory)
    {
      std::vector<std::string> libraries;
      for (const std::string &name :
           dealii::Utilities::split_string_list(value))
        {
          if (name.empty())
            continue;
          const std::filesystem::path path(name);
          if (!directory.empty() && path.is_relative() &&
              name.find('/') != std::string::npos)
            libraries.push_back((std::filesystem::path(directory) / path)
                                  .lexically_normal()
                                  .string());
          else
            libraries.push_back(name);
        }
      return libraries;
    }



    namespace
    {
      /**
       * The value of the entry as the scene file @p scene_file and the
       * overrides @p overrides give it (the last override that sets it
       * wins), with the directory its relative paths are relative to; an
       * empty value if neither sets it.
       */
      std::pair<std::string, std::string>
      value_named(const std::string              &scene_file,
                  const std::vector<std::string> &overrides)
      {
        std::pair<std::string, std::string> named;
        if (!scene_file.empty())
          {
            std::ifstream     in(scene_file);
            std::stringstream text;
            if (in)
              text << in.rdbuf();
            const auto [found, value] = value_in_scene(text.str());
            if (found)
              named = {
                value,
                std::filesystem::absolute(scene_file).parent_path().string()};
          }
        for (const std::string &assignment : overrides)
          {
            const auto equals = assignment.find('=');
            if (equals != std::string::npos &&
                collapse_white_space(assignment.substr(0, equals)) == entry)
              named = {assignment.substr(equals + 1),
                       std::filesystem::current_path().string()};
          }
        return named;
      }
    } // namespace



    std::vector<std::string>
    libraries_named(const std::string              &scene_file,
                    const std::vector<std::string> &overrides)
    {
      const auto [value, directory] = value_named(scene_file, overrides);
      return split_value(value, directory);
    }



    void
    check_read(const dealii::ParameterHandler &prm,
               const std::string              &scene_file,
               const std::vector<std::string> &overrides)
    {
      const std::string value = prm.get(entry);
      if (split_value(value, "") !=
          split_value(value_named(scene_file, overrides).first, ""))
        throw InputError(
          "'" + entry + "' = '" + value +
          "' is set where it is read too late (in a file the scene "
          "includes?): the libraries are loaded before the scene is read, "
          "from the entry in the scene file itself or from --set.");
    }



    std::string
    check_registrations(const std::string &where)
    {
      auto &errors = plugin_registration_errors();
      if (errors.empty())
        return "";
      std::string message = where + ": " + errors.front();
      for (std::size_t i = 1; i < errors.size(); ++i)
        message += "; " + errors[i];
      errors.clear();
      return message + ".";
    }



    std::string
    load(const std::vector<std::string> &libraries)
    {
      std::string error = check_registrations("IMPM's own plugins");
      if (!error.empty())
        return error;
      for (const std::string &library : libraries)
        {
          if (dlopen(library.c_str(), RTLD_NOW | RTLD_GLOBAL) == nullptr)
            {
              const char *reason = dlerror();
              return "'" + entry + "': cannot load '" + library +
                     "': " + collapse_white_space(reason ? reason : "") + ".";
            }
          error = check_registrations("'" + entry + "': the library '" +
                                      library + "'");
          if (!error.empty())
            return error;
        }
      return "";
    }
  } // namespace SharedLibraries
} // namespace impm
