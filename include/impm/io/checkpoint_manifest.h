#ifndef impm_io_checkpoint_manifest_h
#define impm_io_checkpoint_manifest_h

#include <string>

namespace impm
{
  /**
   * @brief The manifest of a checkpoint directory: every file in it with
   * its size and its CRC-32 (zlib's), in the file `manifest.txt`, whose
   * last line holds the CRC-32 of the lines before it.
   *
   * The manifest is written last, atomically, so that its presence marks a
   * checkpoint as complete; verify() reads every file back before anything
   * of the checkpoint is used, so that a damaged checkpoint (a truncated,
   * zeroed or altered file, one missing) is refused with the name of the
   * file instead of being read by p4est or the particle handler.
   */
  namespace CheckpointManifest
  {
    /** The name of the manifest file in a checkpoint directory. */
    constexpr const char *file_name = "manifest.txt";

    /**
     * @brief Write the manifest of every regular file in @p directory (the
     * manifest itself and temporaries excepted); an error naming the
     * file if one cannot be read or the manifest cannot be written.
     */
    void
    write(const std::string &directory);

    /**
     * @brief Check every file of the manifest in @p directory against its
     * size and checksum: "" if all agree, else the reason, naming the
     * first file that does not (or the manifest itself).
     */
    std::string
    verify(const std::string &directory);
  } // namespace CheckpointManifest
} // namespace impm

#endif
