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
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw std::runtime_error("Cannot rename " + temporary + " to " + path +
                               ".");
  }



  void
  write_file_atomically(const std::string &path, const std::string &text)
  {
    write_file_atomically(path, [&text](std::ostream &out) { out << text; });
  }
} // namespace impm
