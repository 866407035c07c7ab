#include <boost/crc.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <slidewave/core/input_error.h>
#include <slidewave/io/checkpoint_manifest.h>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace slidewave
{
  namespace io
  {
    namespace
    {
      namespace fs = std::filesystem;

      const std::string header = "SlideWave checkpoint manifest 1";

      std::string
      hexadecimal(const unsigned long crc)
      {
        char text[16];
        std::snprintf(text, sizeof(text), "%08lx", crc);
        return text;
      }
    } // namespace



    const std::string CheckpointManifest::file_name = "manifest.txt";



    unsigned long
    CheckpointManifest::checksum(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      if (!in)
        throw std::runtime_error("cannot read " + path);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      while (in)
        {
          in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
          crc.process_bytes(buffer.data(), static_cast<std::size_t>(in.gcount()));
        }
      if (in.bad())
        throw std::runtime_error("cannot read " + path);
      return crc.checksum();
    }



    void
    CheckpointManifest::write(const std::string &folder, const unsigned int n_ranks)
    {
      // Sorted by name: the manifest of the same files is the same text.
      std::set<std::string> names;
      for (const auto &entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().filename() != file_name)
          names.insert(entry.path().filename().string());
      std::ostringstream text;
      text << header << '\n' << "ranks " << n_ranks << '\n';
      for (const auto &name : names)
        {
          const fs::path path = fs::path(folder) / name;
          text << "file " << name << ' ' << fs::file_size(path) << ' '
               << hexadecimal(checksum(path.string())) << '\n';
        }
      // The end, so that a manifest cut short at a line's end is seen.
      text << "end " << names.size() << '\n';
      std::ofstream out(fs::path(folder) / file_name);
      out << text.str();
      out.close();
      require_written(out, (fs::path(folder) / file_name).string());
    }



    std::string
    CheckpointManifest::check(const std::string &folder)
    {
      const fs::path manifest = fs::path(folder) / file_name;
      if (!fs::exists(manifest))
        return "it has no " + file_name
               + " (written by a SlideWave before checkpoints were verified, or damaged): "
                 "its files cannot be checked";
      std::ifstream in(manifest);
      std::string   line;
      if (!std::getline(in, line) || line != header)
        return file_name + " is damaged (its first line is not '" + header + "')";
      unsigned int line_number = 1, n_files = 0;
      bool         has_ranks = false, has_end = false;
      while (std::getline(in, line))
        {
          if (has_end)
            return file_name + " is damaged (line " + std::to_string(line_number + 1)
                   + " follows its end)";
          ++line_number;
          std::istringstream words(line);
          std::string        kind, name, crc_text, rest;
          unsigned long long size = 0;
          const std::string  where
            = file_name + " is damaged (line " + std::to_string(line_number) + ": '" + line + "'";
          if (!(words >> kind))
            return where + " is empty)";
          if (kind == "ranks")
            {
              unsigned int ranks = 0;
              if (!(words >> ranks) || ranks == 0 || (words >> rest))
                return where + " is not 'ranks N')";
              has_ranks = true;
              continue;
            }
          if (kind == "end")
            {
              unsigned int n = 0;
              if (!(words >> n) || n != n_files || (words >> rest))
                return where + " is not 'end " + std::to_string(n_files) + "')";
              has_end = true;
              continue;
            }
          if (kind != "file" || !(words >> name >> size >> crc_text) || (words >> rest)
              || name.find('/') != std::string::npos || name == "." || name == "..")
            return where + " is not 'file NAME SIZE CRC-32')";
          char               *end = nullptr;
          const unsigned long crc = std::strtoul(crc_text.c_str(), &end, 16);
          if (crc_text.size() != 8 || *end != '\0')
            return where + " has no 8-digit CRC-32)";
          const fs::path path = fs::path(folder) / name;
          if (!fs::is_regular_file(path))
            return "'" + name + "' is missing (" + file_name + " lists it)";
          const auto actual = fs::file_size(path);
          if (actual != size)
            return "'" + name + "' has " + std::to_string(actual) + " bytes, " + file_name
                   + " says " + std::to_string(size);
          const unsigned long actual_crc = checksum(path.string());
          if (actual_crc != crc)
            return "'" + name + "' has the CRC-32 " + hexadecimal(actual_crc) + ", " + file_name
                   + " says " + crc_text + ": its content has changed";
          ++n_files;
        }
      if (!has_end)
        return file_name + " is damaged (it has no 'end' line: it was cut short)";
      if (!has_ranks || n_files == 0)
        return file_name + " is damaged (it lists no files or no number of ranks)";
      return "";
    }
  } // namespace io
} // namespace slidewave
