#ifndef impm_io_log_file_h
#define impm_io_log_file_h

#include <fstream>
#include <stdexcept>
#include <string>

namespace impm
{
  /**
   * @brief A file that grows by whole lines during a run (steps.csv,
   * newton.csv): opened empty, flushed after each load step, and every
   * write checked. A failed open or write is an error naming the file.
   */
  class LogFile
  {
  public:
    /** @brief Create (or empty) the file @p path. */
    void
    open(const std::string &path)
    {
      file_path = path;
      file.open(path);
      if (!file)
        throw std::runtime_error("Cannot write the file " + path + ".");
    }

    /** @brief The stream to write lines to. */
    std::ostream &
    stream()
    {
      return file;
    }

    /** @brief Flush what was written and check that it reached the file. */
    void
    flush()
    {
      file.flush();
      if (!file)
        throw std::runtime_error("Writing the file " + file_path + " failed.");
    }

  private:
    std::string   file_path;
    std::ofstream file;
  };
} // namespace impm

#endif
