#include <impm/base/errors.h>
#include <impm/io/run_state.h>

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace impm
{
  namespace
  {
    std::string
    exact(const double value)
    {
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), "%.17g", value);
      return buffer;
    }
  } // namespace



  void
  RunState::set(const std::string &key, const double value)
  {
    values[key] = exact(value);
  }



  void
  RunState::set(const std::string &key, const std::string &value)
  {
    if (value.find('\n') != std::string::npos)
      throw std::logic_error("RunState: a value of '" + key +
                             "' holds a line break.");
    values[key] = value;
  }



  void
  RunState::set(const std::string &key, const std::vector<double> &list)
  {
    std::string text;
    for (const double value : list)
      text += (text.empty() ? "" : " ") + exact(value);
    values[key] = text;
  }



  const std::string &
  RunState::get_string(const std::string &key) const
  {
    const auto found = values.find(key);
    if (found == values.end())
      throw CollectiveError("The checkpoint " + source + " lacks '" + key +
                            "': it was written by another version of IMPM "
                            "or is damaged.");
    return found->second;
  }



  double
  RunState::get_double(const std::string &key) const
  {
    return std::stod(get_string(key));
  }



  std::vector<double>
  RunState::get_list(const std::string &key) const
  {
    std::istringstream  in(get_string(key));
    std::vector<double> list;
    std::string         word;
    while (in >> word)
      list.push_back(std::stod(word));
    return list;
  }



  std::string
  RunState::to_text() const
  {
    std::string text;
    for (const auto &[key, value] : values)
      text += key + " = " + value + "\n";
    return text;
  }



  RunState
  RunState::from_text(const std::string &text, const std::string &source)
  {
    RunState           state;
    std::istringstream in(text);
    std::string        line;
    state.source = source;
    while (std::getline(in, line))
      {
        const auto separator = line.find(" = ");
        if (separator != std::string::npos)
          state.values[line.substr(0, separator)] = line.substr(separator + 3);
      }
    return state;
  }
} // namespace impm
