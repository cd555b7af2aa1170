#ifndef impm_io_free_space_h
#define impm_io_free_space_h

#include <cstdint>
#include <string>

namespace impm
{
  /**
   * @brief Whether a write of about @p bytes into @p directory, none of whose
   * files is larger than @p largest_file bytes, can be expected to fit: the
   * free space of the file system (for an unprivileged user) and the
   * process's file-size limit (ulimit -f) are compared with it.
   *
   * @param directory The directory written into.
   * @param bytes The bytes the write will add, an estimate.
   * @param largest_file The largest single file among them.
   * @param what What is written, for the message ("the checkpoint").
   * @return Empty if it fits (or the free space cannot be known), else one
   *   sentence that says what does not fit and what is left; nothing has
   *   been written.
   */
  std::string
  space_shortage(const std::string   &directory,
                 const std::uintmax_t bytes,
                 const std::uintmax_t largest_file,
                 const std::string   &what);

  /**
   * @brief Whether a file written by another library (MPI-IO, HDF5, p4est)
   * was cut at the process's file-size limit: a write past it returns a
   * short count that such libraries may not report, and the file then
   * ends exactly at the limit.
   *
   * @param path The file just written.
   * @return Whether it is at least as large as the limit.
   */
  bool
  reached_file_size_limit(const std::string &path);
} // namespace impm

#endif
