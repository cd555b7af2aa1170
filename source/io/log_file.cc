#include <impm/io/atomic_file.h>
#include <impm/io/log_file.h>

#include <cerrno>
#include <filesystem>
#include <stdexcept>

namespace impm
{
  void
  LogFile::open(const std::string &path)
  {
    file_path = path;
    errno     = 0;
    file.open(path, std::ios::out | std::ios::trunc);
    if (!file)
      throw std::runtime_error("Cannot write the file " + path +
                               system_reason() + ".");
    complete_size = 0;
  }



  void
  LogFile::reopen(const std::string &path, const std::streamoff size)
  {
    file_path = path;
    std::error_code code;
    std::filesystem::resize_file(path, size, code);
    if (code)
      throw std::runtime_error("Cannot continue the file " + path + " (" +
                               code.message() + ").");
    errno = 0;
    file.open(path, std::ios::out | std::ios::app);
    if (!file)
      throw std::runtime_error("Cannot write the file " + path +
                               system_reason() + ".");
    complete_size = size;
  }



  void
  LogFile::flush()
  {
    const std::string text = pending.str();
    pending.str("");
    errno = 0;
    file << text;
    file.flush();
    if (file)
      {
        complete_size += static_cast<std::streamoff>(text.size());
        return;
      }
    const std::string reason = system_reason();
    file.close();
    std::error_code ignored;
    std::filesystem::resize_file(file_path, complete_size, ignored);
    throw std::runtime_error("Writing the file " + file_path + " failed" +
                             reason + "; it keeps its complete lines.");
  }
} // namespace impm
