#include <impm/io/atomic_file.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace impm
{
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".tmp";
    {
      std::ofstream out(temporary);
      if (!out)
        throw std::runtime_error("Cannot write the file " + path + ".");
      write(out);
      out.flush();
      if (!out)
        throw std::runtime_error("Writing the file " + path + " failed.");
    }
    rename_or_throw(temporary, path);
  }



  void
  rename_or_throw(const std::string &from, const std::string &to)
  {
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw std::runtime_error("Cannot rename " + from + " to " + to + ".");
  }



  void
  write_file_atomically(const std::string &path, const std::string &text)
  {
    write_file_atomically(path, [&text](std::ostream &out) { out << text; });
  }
} // namespace impm
