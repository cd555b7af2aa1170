#ifndef impm_io_atomic_file_h
#define impm_io_atomic_file_h

#include <functional>
#include <ostream>
#include <string>

namespace impm
{
  /**
   * @brief Write a file so that it is never seen half-written: the content
   * goes to `path.tmp`, which is closed (the close checked), synced to the
   * disk (`fsync`) and renamed to @p path only when complete, and the
   * directory is synced after the rename, so that a crash of the machine
   * too leaves the previous or the new content. A failed open, write,
   * close, sync or rename is an error naming the file.
   *
   * @param path The final name.
   * @param write Writes the content to the stream it is given.
   */
  void
  write_file_atomically(const std::string                         &path,
                        const std::function<void(std::ostream &)> &write);

  /**
   * @brief `fsync` the file (or, with @p directory, the directory) @p path:
   * false if it cannot be opened or synced (errno says why).
   */
  bool
  sync_file(const std::string &path, const bool directory = false);

  /**
   * @brief Rename @p from to @p to (the last step of a file written under
   * a temporary name by another writer), then sync the directory of @p to;
   * a failed rename is an error naming both.
   */
  void
  rename_or_throw(const std::string &from, const std::string &to);

  /**
   * @brief " (the system's reason)" for the last failed system call (from
   * errno), or "" if none is recorded.
   */
  std::string
  system_reason();

  /**
   * @brief As above, for content already held in a string.
   */
  void
  write_file_atomically(const std::string &path, const std::string &text);
} // namespace impm

#endif
