#include <impm/io/atomic_file.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace impm
{
  std::string
  system_reason()
  {
    return errno == 0 ? std::string() :
                        std::string(" (") + std::strerror(errno) + ")";
  }



  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".tmp";
    std::string       failure;
    {
      errno = 0;
      std::ofstream out(temporary);
      if (!out)
        throw std::runtime_error("Cannot write the file " + path +
                                 system_reason() + ".");
      try
        {
          write(out);
          out.flush();
          // Closing writes what the stream still holds: checked too.
          out.close();
        }
      catch (...)
        {
          // A writer that checks its stream itself (deal.II's) throws;
          // the stream's state says why.
          out.setstate(std::ios::badbit);
        }
      if (!out)
        failure = "Writing the file " + path + " failed" + system_reason() +
                  "; the previous version, if any, is kept.";
      else if (!sync_file(temporary))
        failure = "Writing the file " + path + " failed (fsync" +
                  system_reason() + "); the previous version, if any, is kept.";
    }
    if (!failure.empty())
      {
        std::remove(temporary.c_str());
        throw std::runtime_error(failure);
      }
    rename_or_throw(temporary, path);
  }



  bool
  sync_file(const std::string &path, const bool directory)
  {
    errno = 0;
    const int descriptor =
      ::open(path.c_str(),
             O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0));
    if (descriptor < 0)
      return false;
    // A file system that cannot sync a directory says EINVAL: nothing to
    // wait for there.
    const bool synced = ::fsync(descriptor) == 0 || errno == EINVAL;
    ::close(descriptor);
    return synced;
  }



  void
  rename_or_throw(const std::string &from, const std::string &to)
  {
    errno = 0;
    if (std::rename(from.c_str(), to.c_str()) != 0)
      throw std::runtime_error("Cannot rename " + from + " to " + to +
                               system_reason() + ".");
    // The rename itself reaches the disk with its directory.
    const std::string parent = std::filesystem::path(to).parent_path().string();
    sync_file(parent.empty() ? "." : parent, true);
  }



  void
  write_file_atomically(const std::string &path, const std::string &text)
  {
    write_file_atomically(path, [&text](std::ostream &out) { out << text; });
  }
} // namespace impm
