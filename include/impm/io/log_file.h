#ifndef impm_io_log_file_h
#define impm_io_log_file_h

#include <fstream>
#include <sstream>
#include <string>

namespace impm
{
  /**
   * @brief A file that grows by whole lines during a run (steps.csv,
   * newton.csv). What a load step writes is collected in memory and
   * appended at flush(), which checks the write; if it fails (a full disk,
   * a file-size limit), the file is cut back to the lines of the last
   * complete flush, so that it never ends in half a line, and the failure is
   * an error naming the file and the cause.
   */
  class LogFile
  {
  public:
    /** @brief Create (or empty) the file @p path. */
    void
    open(const std::string &path);

    /**
     * @brief Continue the file @p path of a resumed run: cut it back to
     * the @p size bytes it had at the checkpoint and append from there.
     */
    void
    reopen(const std::string &path, const std::streamoff size);

    /** @brief The stream the next lines go to (held until flush()). */
    std::ostream &
    stream()
    {
      return pending;
    }

    /** @brief Append the pending lines and check that they reached the
     * file. */
    void
    flush();

    /** @brief The size in bytes of the complete lines in the file. */
    std::streamoff
    size() const
    {
      return complete_size;
    }

  private:
    std::string        file_path;
    std::ofstream      file;
    std::ostringstream pending;
    std::streamoff     complete_size = 0;
  };
} // namespace impm

#endif
