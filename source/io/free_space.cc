#include <impm/base/errors.h>
#include <impm/io/free_space.h>

#include <sys/resource.h>
#include <sys/statvfs.h>

#include <filesystem>

namespace impm
{
  namespace
  {
    /** The process's file-size limit in bytes (RLIM_INFINITY if none). */
    rlim_t
    file_size_limit()
    {
      struct rlimit limit;
      if (getrlimit(RLIMIT_FSIZE, &limit) != 0)
        return RLIM_INFINITY;
      return limit.rlim_cur;
    }
  } // namespace



  std::string
  space_shortage(const std::string   &directory,
                 const std::uintmax_t bytes,
                 const std::uintmax_t largest_file,
                 const std::string   &what)
  {
    const rlim_t limit = file_size_limit();
    if (limit != RLIM_INFINITY && largest_file >= limit)
      return "Not writing " + what + ": a file of about " +
             bytes_in_words(largest_file) +
             " exceeds this process's file-size limit of " +
             bytes_in_words(limit) + " (ulimit -f)";
    struct statvfs file_system;
    if (statvfs(directory.c_str(), &file_system) != 0)
      return "";
    const std::uintmax_t available =
      std::uintmax_t(file_system.f_bavail) * file_system.f_frsize;
    if (bytes > available)
      return "Not writing " + what + ": about " + bytes_in_words(bytes) +
             " are needed and " + bytes_in_words(available) + " are free in " +
             directory;
    return "";
  }



  bool
  reached_file_size_limit(const std::string &path)
  {
    const rlim_t limit = file_size_limit();
    if (limit == RLIM_INFINITY)
      return false;
    std::error_code      code;
    const std::uintmax_t size = std::filesystem::file_size(path, code);
    return !code && size >= limit;
  }
} // namespace impm
