#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/io/scene_input.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace impm
{
  namespace SceneInput
  {
    namespace
    {
      using Tree = boost::property_tree::ptree;

      std::string
      join(const std::vector<std::string> &parts, const std::string &glue)
      {
        std::string result;
        for (const auto &part : parts)
          result += (result.empty() ? "" : glue) + part;
        return result;
      }

      /** The words of a line after its comment is removed. */
      std::string
      strip_comment(const std::string &line)
      {
        for (std::size_t i = 0; i < line.size(); ++i)
          if (line[i] == '#' && (i == 0 || line[i - 1] != '\\'))
            return line.substr(0, i);
        return line;
      }

      /**
       * The lines of a scene as the parser sees them: one per file line,
       * a line ending in a backslash joined with the next.
       */
      struct SceneLines
      {
        explicit SceneLines(const std::string &text)
        {
          std::istringstream in(text);
          std::string        line;
          while (std::getline(in, line))
            lines.push_back(strip_comment(line));
        }

        /**
         * The subsections open when line @p line_number (1-based) is
         * read, with the line of each 'subsection' statement.
         */
        std::vector<std::pair<std::string, unsigned int>>
        open_subsections(const unsigned int line_number) const
        {
          std::vector<std::pair<std::string, unsigned int>> path;
          for (unsigned int i = 0; i + 1 < line_number && i < lines.size(); ++i)
            {
              const std::string line = dealii::Utilities::trim(lines[i]);
              std::string       keyword =
                line.substr(0, std::min(line.find(' '), line.size()));
              std::transform(keyword.begin(),
                             keyword.end(),
                             keyword.begin(),
                             [](const char c) { return std::tolower(c); });
              if (keyword == "subsection")
                path.emplace_back(collapse_white_space(line.substr(10)), i + 1);
              else if (keyword == "end" && !path.empty())
                path.pop_back();
            }
          return path;
        }

        /** The subsection path at line @p line_number, as "A/B/". */
        std::string
        path_at(const unsigned int line_number) const
        {
          std::string path;
          for (const auto &section : open_subsections(line_number))
            path += section.first + "/";
          return path;
        }

        /** Whether any line sets an entry. */
        bool
        sets_an_entry() const
        {
          for (const auto &line : lines)
            {
              const std::string words = dealii::Utilities::trim(line);
              if (words.size() > 3 && (words.compare(0, 4, "set ") == 0 ||
                                       words.compare(0, 4, "SET ") == 0 ||
                                       words.compare(0, 8, "include ") == 0 ||
                                       words.compare(0, 8, "INCLUDE ") == 0))
                return true;
            }
          return false;
        }

        std::vector<std::string> lines;
      };

      /** The declared entries and subsections of @p prm as a tree. */
      Tree
      declared_tree(const dealii::ParameterHandler &prm)
      {
        std::stringstream json;
        prm.print_parameters(json, dealii::ParameterHandler::JSON);
        Tree tree;
        boost::property_tree::read_json(json, tree);
        return tree;
      }

      bool
      is_entry(const Tree &node)
      {
        return node.find("value") != node.not_found() &&
               node.find("pattern_description") != node.not_found();
      }

      /** The node at the subsection path @p path ("A/B/"), if any. */
      const Tree *
      find_subsection(const Tree &tree, const std::string &path)
      {
        const Tree       *node = &tree;
        std::stringstream in(path);
        std::string       section;
        while (std::getline(in, section, '/'))
          {
            if (section.empty())
              continue;
            const auto child = node->find(section);
            if (child == node->not_found() || is_entry(child->second))
              return nullptr;
            node = &child->second;
          }
        return node;
      }

      /** Edit distance between two names, ignoring case. */
      unsigned int
      distance(const std::string &a, const std::string &b)
      {
        std::vector<unsigned int> row(b.size() + 1);
        for (unsigned int j = 0; j <= b.size(); ++j)
          row[j] = j;
        for (unsigned int i = 1; i <= a.size(); ++i)
          {
            unsigned int diagonal = row[0];
            row[0]                = i;
            for (unsigned int j = 1; j <= b.size(); ++j)
              {
                const unsigned int above = row[j];
                row[j]                   = std::min(
                  {row[j] + 1,
                                     row[j - 1] + 1,
                                     diagonal +
                                       (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0u :
                                                                                           1u)});
                diagonal = above;
              }
          }
        return row[b.size()];
      }

      /**
       * " (did you mean 'X'?)" for the closest of the names under
       * @p node (entries if @p entries, else subsections), or "".
       */
      std::string
      suggestion(const Tree *node, const std::string &name, const bool entries)
      {
        if (node == nullptr)
          return "";
        std::string  best;
        unsigned int best_distance = 4;
        for (const auto &child : *node)
          if (is_entry(child.second) == entries)
            {
              const unsigned int d = distance(name, child.first);
              if (d < best_distance)
                {
                  best          = child.first;
                  best_distance = d;
                }
            }
        return best.empty() ? "" : " (did you mean '" + best + "'?)";
      }

      std::string
      quoted_path(const std::string &path)
      {
        return path.empty() ?
                 "at the top level" :
                 "in subsection '" + path.substr(0, path.size() - 1) + "'";
      }

      /**
       * The InputError for deal.II's exception @p exception, thrown while
       * parsing @p text (named @p name) into @p prm.
       */
      InputError
      translate(const dealii::ExceptionBase    &exception,
                const std::string              &text,
                const std::string              &name,
                const dealii::ParameterHandler &prm)
      {
        std::ostringstream info;
        exception.print_info(info);
        const std::string message = collapse_white_space(info.str());
        const SceneLines  lines(text);

        std::smatch             match;
        static const std::regex located(
          R"(^Line <(\d+)> of file <(.+?)>?: (.*)$)");
        if (!std::regex_match(message, match, located))
          {
            if (message.find("unequal numbers of 'subsection' and 'end'") !=
                std::string::npos)
              {
                const auto open = lines.open_subsections(
                  static_cast<unsigned int>(lines.lines.size() + 1));
                if (!open.empty())
                  return InputError(name + ":" +
                                    std::to_string(open.back().second) +
                                    ": 'subsection " + open.back().first +
                                    "' has no matching 'end'.");
                return InputError(name + ": the file has more 'end' lines than "
                                         "'subsection' lines.");
              }
            return InputError(name + ": " + message);
          }
        const unsigned int line_number = std::stoul(match[1].str());
        const std::string  where       = name + ":" + match[1].str() + ": ";
        const std::string  rest        = match[3].str();
        const std::string  path        = lines.path_at(line_number);
        const Tree         tree        = declared_tree(prm);

        static const std::regex bad_value(
          R"(^The entry value ?(.*) for the entry named (.*) does not match the given pattern: (.*)$)");
        static const std::regex no_entry(
          R"(^No entry with name <(.*)> was declared in the current subsection\.$)");
        static const std::regex no_subsection(
          R"(^There is no such subsection to be entered: (.*)$)");
        if (std::regex_match(rest, match, bad_value))
          return InputError(where + "'" + path + match[2].str() + "' = '" +
                            match[1].str() + "' is not allowed: it must be " +
                            describe_pattern(match[3].str()) + ".");
        if (std::regex_match(rest, match, no_entry))
          return InputError(
            where + "there is no entry '" + match[1].str() + "' " +
            quoted_path(path) +
            suggestion(find_subsection(tree, path), match[1].str(), true) +
            "; impm --print-parameters lists every entry.");
        if (std::regex_match(rest, match, no_subsection))
          {
            // deal.II names the whole path, its parts joined by dots.
            std::string dotted_path = path;
            std::replace(dotted_path.begin(), dotted_path.end(), '/', '.');
            const std::string full    = match[1].str();
            const std::string section = full.rfind(dotted_path, 0) == 0 ?
                                          full.substr(dotted_path.size()) :
                                          full;
            return InputError(
              where + "there is no subsection '" + section + "' " +
              quoted_path(path) +
              suggestion(find_subsection(tree, path), section, false) +
              "; impm --print-parameters lists every subsection.");
          }
        const std::string line =
          line_number <= lines.lines.size() ?
            collapse_white_space(lines.lines[line_number - 1]) :
            "";
        if (rest.find("Invalid format of 'set'") != std::string::npos)
          return InputError(where + "'" + line +
                            "' is not of the form 'set Entry = value'.");
        if (rest.find("could not be parsed") != std::string::npos)
          return InputError(where + "'" + line +
                            "' is not a 'set', 'subsection', 'end' or "
                            "'include' line.");
        return InputError(where + rest);
      }
    } // namespace



    void
    parse_text(dealii::ParameterHandler &prm,
               const std::string        &text,
               const std::string        &name)
    {
      std::istringstream in(text);
      try
        {
          prm.parse_input(in, name, "", false);
        }
      catch (const dealii::ExceptionBase &exception)
        {
          throw translate(exception, text, name, prm);
        }
      if (!SceneLines(text).sets_an_entry())
        throw InputError(name +
                         ": the scene sets no entry (an empty file?); run "
                         "impm without a scene for the default one.");
    }



    void
    resolve_paths(dealii::ParameterHandler &prm, const std::string &scene_file)
    {
      if (scene_file.empty())
        return;
      const auto directory =
        std::filesystem::absolute(scene_file).parent_path();
      for (unsigned int k = 1;; ++k)
        {
          const std::string subsection = "Rigid body " + std::to_string(k);
          if (!prm.subsection_path_exists({subsection}))
            break;
          prm.enter_subsection(subsection);
          const std::filesystem::path file = prm.get("STL file");
          if (!file.empty() && file.is_relative())
            prm.set("STL file", (directory / file).lexically_normal().string());
          prm.leave_subsection();
        }
    }



    void
    parse_file(dealii::ParameterHandler &prm, const std::string &file_name)
    {
      // A directory opens as an empty stream on Linux.
      std::error_code error;
      if (std::filesystem::is_directory(file_name, error))
        throw InputError("Cannot read the scene file '" + file_name +
                         "': it is a directory.");
      std::ifstream in(file_name);
      if (!in)
        throw InputError("Cannot read the scene file '" + file_name +
                         "': " + std::strerror(errno) + ".");
      std::stringstream text;
      text << in.rdbuf();
      if (in.bad())
        throw InputError("Cannot read the scene file '" + file_name + "'.");
      // A UTF-8 byte-order mark (some editors on Windows write one) is
      // not part of the scene.
      std::string content = text.str();
      if (content.rfind("\xEF\xBB\xBF", 0) == 0)
        content.erase(0, 3);
      parse_text(prm, content, file_name);
    }



    namespace
    {
      /** apply_overrides() for one assignment, with @p tree the declared
       *  entries (the same for every assignment: setting a value declares
       *  nothing). */
      void
      apply_override(dealii::ParameterHandler &prm,
                     const Tree               &tree,
                     const std::string        &assignment)
      {
        const std::string where  = "--set '" + assignment + "': ";
        const auto        equals = assignment.find('=');
        if (equals == std::string::npos)
          throw InputError(where + "expected \"Subsection/Entry=value\".");
        const std::string path =
          dealii::Utilities::trim(assignment.substr(0, equals));
        const std::string value =
          dealii::Utilities::trim(assignment.substr(equals + 1));
        const auto        slash = path.rfind('/');
        const std::string sections =
          slash == std::string::npos ? "" : path.substr(0, slash + 1);
        const std::string entry =
          slash == std::string::npos ? path : path.substr(slash + 1);

        const Tree *section = find_subsection(tree, sections);
        if (section == nullptr)
          throw InputError(where + "there is no subsection '" +
                           sections.substr(0, sections.size() - 1) +
                           "'; impm --print-parameters lists every entry.");
        const auto found = section->find(entry);
        if (found == section->not_found() || !is_entry(found->second))
          throw InputError(where + "there is no entry '" + entry + "' " +
                           quoted_path(sections) +
                           suggestion(section, entry, true) + ".");

        std::vector<std::string> parts;
        std::stringstream        in(sections);
        std::string              part;
        while (std::getline(in, part, '/'))
          if (!part.empty())
            parts.push_back(part);
        for (const auto &name : parts)
          prm.enter_subsection(name);
        try
          {
            prm.set(entry, value);
          }
        catch (const dealii::ExceptionBase &)
          {
            for (unsigned int i = 0; i < parts.size(); ++i)
              prm.leave_subsection();
            throw InputError(where + "'" + path + "' = '" + value +
                             "' is not allowed: it must be " +
                             describe_pattern(found->second.get<std::string>(
                               "pattern_description")) +
                             ".");
          }
        for (unsigned int i = 0; i < parts.size(); ++i)
          prm.leave_subsection();
      }
    } // namespace



    void
    apply_overrides(dealii::ParameterHandler       &prm,
                    const std::vector<std::string> &assignments)
    {
      if (assignments.empty())
        return;
      // The declared entries printed and read back once (about 10 ms),
      // not once per assignment.
      const Tree tree = declared_tree(prm);
      for (const auto &assignment : assignments)
        apply_override(prm, tree, assignment);
    }



    namespace
    {
      void
      check_numbers_below(const Tree &node, const std::string &path)
      {
        for (const auto &child : node)
          {
            if (!is_entry(child.second))
              {
                check_numbers_below(child.second, path + child.first + "/");
                continue;
              }
            const std::string pattern =
              child.second.get<std::string>("pattern_description");
            if (pattern.find("Double") == std::string::npos)
              continue;
            const std::string value = child.second.get<std::string>("value");
            std::stringstream in(value);
            std::string       number;
            while (
              std::getline(in, number, pattern.find("List") == 0 ? ',' : '\0'))
              {
                number = dealii::Utilities::trim(number);
                if (number.empty())
                  continue;
                errno             = 0;
                const double read = std::strtod(number.c_str(), nullptr);
                if (!std::isfinite(read) ||
                    (errno == ERANGE && std::abs(read) < 1.))
                  throw InputError(
                    "'" + path + child.first + "' = '" + value +
                    "' is not allowed: " + number +
                    (std::isfinite(read) ?
                       " is too close to zero to be represented (use 0 or "
                       "a number of magnitude above 1e-300)." :
                       " is not a finite number."));
              }
          }
      }
    } // namespace



    void
    check_numbers(const dealii::ParameterHandler &prm)
    {
      check_numbers_below(declared_tree(prm), "");
    }



    std::string
    describe_pattern(const std::string &description)
    {
      static const std::string max_int = "2147483647";
      static const std::string min_int = "-2147483648";
      std::smatch              match;
      static const std::regex  integer(
        R"(^\[Integer range (\S+)\.\.\.(\S+) \(inclusive\)\]$)");
      static const std::regex number(
        R"(^\[Double (\S+)\.\.\.(\S+) \(inclusive\)\]$)");
      static const std::regex selection(R"(^\[Selection (.*) \]$)");
      static const std::regex list(
        R"(^\[List of <(.*)> of length (\d+)\.\.\.(\d+) \(inclusive\)(?: separated by <(.*)>)?\]$)");
      if (std::regex_match(description, match, integer))
        {
          const bool low = match[1].str() != min_int;
          const bool up  = match[2].str() != max_int;
          if (low && up)
            return "an integer from " + match[1].str() + " to " +
                   match[2].str();
          if (low)
            return "an integer >= " + match[1].str();
          if (up)
            return "an integer <= " + match[2].str();
          return "an integer";
        }
      if (std::regex_match(description, match, number))
        {
          const bool low = match[1].str() != "-MAX_DOUBLE";
          const bool up  = match[2].str() != "MAX_DOUBLE";
          if (low && up)
            return "a number from " + match[1].str() + " to " + match[2].str();
          if (low)
            return "a number >= " + match[1].str();
          if (up)
            return "a number <= " + match[2].str();
          return "a number";
        }
      if (std::regex_match(description, match, selection))
        {
          std::vector<std::string> options;
          std::stringstream        in(match[1].str());
          std::string              option;
          while (std::getline(in, option, '|'))
            options.push_back("'" + option + "'");
          return "one of " + join(options, ", ");
        }
      if (std::regex_match(description, match, list))
        {
          const std::string lower = match[2].str(), upper = match[3].str();
          const std::string count = lower == upper ? lower :
                                    lower == "0"   ? "up to " + upper :
                                                     lower + " to " + upper;
          return count + " comma-separated values, each " +
                 describe_pattern(match[1].str());
        }
      if (description == "[Bool]")
        return "true or false";
      if (description == "[DirectoryName]")
        return "a directory name";
      if (description.rfind("[FileName", 0) == 0)
        return "a file name";
      return description;
    }
  } // namespace SceneInput
} // namespace impm
