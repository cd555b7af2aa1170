#include <impm/io/atomic_file.h>
#include <impm/io/checkpoint_manifest.h>

#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace impm
{
  namespace CheckpointManifest
  {
    namespace
    {
      namespace fs = std::filesystem;

      /** A file's size and CRC-32 as read. */
      struct FileSum
      {
        std::uintmax_t size  = 0;
        unsigned long  crc32 = 0;
      };

      /** The size and CRC-32 of @p path; throws if it cannot be read (or,
       *  with @p sync, synced to the disk). */
      FileSum
      sum_file(const fs::path &path, const bool sync = false)
      {
        std::FILE *file = std::fopen(path.c_str(), "rb");
        if (file == nullptr)
          throw std::runtime_error("cannot read " + path.string() +
                                   system_reason());
        FileSum           sum;
        std::vector<char> buffer(1 << 20);
        sum.crc32 = crc32(0L, Z_NULL, 0);
        std::size_t n;
        while ((n = std::fread(buffer.data(), 1, buffer.size(), file)) > 0)
          {
            sum.crc32 = crc32(sum.crc32,
                              reinterpret_cast<const Bytef *>(buffer.data()),
                              static_cast<uInt>(n));
            sum.size += n;
          }
        errno = 0;
        const bool failed =
          std::ferror(file) != 0 ||
          (sync && ::fsync(fileno(file)) != 0 && errno != EINVAL);
        std::fclose(file);
        if (failed)
          throw std::runtime_error("cannot read " + path.string() +
                                   system_reason());
        return sum;
      }

      /** The CRC-32 of @p text. */
      unsigned long
      sum_text(const std::string &text)
      {
        return crc32(crc32(0L, Z_NULL, 0),
                     reinterpret_cast<const Bytef *>(text.data()),
                     static_cast<uInt>(text.size()));
      }

      const std::string last_key = "manifest crc32 ";
    } // namespace



    void
    write(const std::string &directory)
    {
      std::vector<std::string> names;
      for (const auto &entry : fs::directory_iterator(directory))
        {
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && name != file_name &&
              name.find('\n') == std::string::npos &&
              !(name.size() > 4 && name.substr(name.size() - 4) == ".tmp"))
            names.push_back(name);
        }
      std::sort(names.begin(), names.end());
      std::ostringstream text;
      text << "# IMPM checkpoint manifest: size in bytes, CRC-32, file\n";
      for (const auto &name : names)
        {
          // The files reach the disk before the manifest names them.
          const FileSum sum = sum_file(fs::path(directory) / name, true);
          text << sum.size << ' ' << sum.crc32 << ' ' << name << '\n';
        }
      const std::string body = text.str();
      write_file_atomically((fs::path(directory) / file_name).string(),
                            body + last_key + std::to_string(sum_text(body)) +
                              "\n");
    }



    std::string
    verify(const std::string &directory)
    {
      const fs::path manifest = fs::path(directory) / file_name;
      std::ifstream  in(manifest, std::ios::binary);
      std::string    text((std::istreambuf_iterator<char>(in)),
                       std::istreambuf_iterator<char>());
      if (!in.good() && !in.eof())
        return manifest.string() + " cannot be read";
      const std::size_t last = text.rfind(last_key);
      if (last == std::string::npos || (last > 0 && text[last - 1] != '\n'))
        return manifest.string() + " is damaged (no checksum line)";
      const std::string body = text.substr(0, last);
      if (text.substr(last) != last_key + std::to_string(sum_text(body)) + "\n")
        return manifest.string() + " is damaged (its checksum differs)";

      std::istringstream lines(body);
      std::string        line;
      while (std::getline(lines, line))
        {
          if (line.empty() || line[0] == '#')
            continue;
          std::istringstream fields(line);
          std::uintmax_t     size  = 0;
          unsigned long      crc32 = 0;
          std::string        name;
          if (fields >> size >> crc32)
            {
              fields.get();
              std::getline(fields, name);
            }
          if (name.empty())
            return manifest.string() + " is damaged (line '" + line + "')";
          const fs::path  path = fs::path(directory) / name;
          std::error_code code;
          const auto      found_size = fs::file_size(path, code);
          if (code)
            return path.string() + " is missing or unreadable (" +
                   code.message() + ")";
          if (found_size != size)
            return path.string() + " has " + std::to_string(found_size) +
                   " bytes, the manifest says " + std::to_string(size);
          try
            {
              if (sum_file(path).crc32 != crc32)
                return path.string() +
                       " is damaged (its CRC-32 differs from the manifest's)";
            }
          catch (const std::exception &exception)
            {
              return exception.what();
            }
        }
      return "";
    }
  } // namespace CheckpointManifest
} // namespace impm
