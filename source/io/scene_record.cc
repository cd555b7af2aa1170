#include <impm/io/scene_record.h>

#include <map>
#include <sstream>

namespace impm
{
  namespace SceneRecord
  {
    namespace
    {
      /** @p text without white space at either end. */
      std::string
      trim(const std::string &text)
      {
        const auto first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos)
          return "";
        const auto last = text.find_last_not_of(" \t\r");
        return text.substr(first, last - first + 1);
      }

      /** The entries of a parameter file as "Subsection/Entry" -> value. */
      std::map<std::string, std::string>
      entries(const std::string &text)
      {
        std::map<std::string, std::string> result;
        std::vector<std::string>           path;
        std::istringstream                 in(text);
        std::string                        line;
        while (std::getline(in, line))
          {
            line = trim(line);
            if (line.rfind("subsection ", 0) == 0)
              path.push_back(trim(line.substr(11)));
            else if (line == "end" && !path.empty())
              path.pop_back();
            else if (line.rfind("set ", 0) == 0)
              {
                const auto  equals = line.find('=');
                std::string name   = trim(line.substr(4, equals - 4));
                for (auto p = path.rbegin(); p != path.rend(); ++p)
                  name = *p + "/" + name;
                result[name] = equals == std::string::npos ?
                                 "" :
                                 trim(line.substr(equals + 1));
              }
          }
        return result;
      }
    } // namespace



    std::string
    to_text(const dealii::ParameterHandler &prm)
    {
      std::ostringstream out;
      prm.print_parameters(out, dealii::ParameterHandler::ShortPRM);
      return out.str();
    }



    bool
    may_change_on_resume(const std::string &path)
    {
      for (const char *subsection : {"Output/", "Checkpoint/", "Testing/"})
        if (path.rfind(subsection, 0) == 0)
          return true;
      // Not 'Time/End time': the steps' progress maps to time through it,
      // so a resumed run with another end time would jump in time (and
      // its load factor, t / End time by default, would jump too). The
      // number of steps and the time step only change the steps to come.
      return path == "Solver/Load steps" || path == "Time/Time step" ||
             path == "Existing output" || path == "Output directory";
    }



    std::vector<std::string>
    differences(const std::string &saved, const std::string &current)
    {
      const auto               before = entries(saved);
      const auto               now    = entries(current);
      std::vector<std::string> list;
      for (const auto &[path, value] : now)
        {
          const auto found = before.find(path);
          if (may_change_on_resume(path))
            continue;
          if (found == before.end())
            list.push_back("'" + path + "' (not in the checkpoint's scene)");
          else if (found->second != value)
            list.push_back("'" + path + "' " + found->second + " -> " + value);
        }
      for (const auto &[path, value] : before)
        if (now.count(path) == 0 && !may_change_on_resume(path))
          list.push_back("'" + path + "' (not in this scene)");
      return list;
    }
  } // namespace SceneRecord
} // namespace impm
