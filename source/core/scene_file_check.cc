#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <slidewave/core/input_error.h>
#include <slidewave/core/scene_file_check.h>
#include <sstream>

namespace slidewave
{
  namespace core
  {
    namespace
    {
      /** A file's identity for loops: its canonical path, or the path as given when it
       *  cannot be resolved (a missing file: deal.II reports it). */
      std::string
      identity(const std::string &filename)
      {
        std::error_code error;
        const auto      canonical = std::filesystem::weakly_canonical(filename, error);
        return error ? filename : canonical.string();
      }

      /** The logical lines of @p text (a trailing backslash continues a line, as deal.II
       *  reads them), comments (from '#') removed, each with the number of its first
       *  physical line. */
      std::vector<std::pair<unsigned int, std::string>>
      logical_lines(std::istream &in)
      {
        std::vector<std::pair<unsigned int, std::string>> lines;
        std::string                                       line, pending;
        unsigned int                                      number = 0, first = 0;
        while (std::getline(in, line))
          {
            ++number;
            if (pending.empty())
              first = number;
            const auto hash = line.find('#');
            if (hash != std::string::npos)
              line.erase(hash);
            if (!line.empty() && line.back() == '\\')
              {
                pending += line.substr(0, line.size() - 1);
                continue;
              }
            lines.emplace_back(first, dealii::Utilities::trim(pending + line));
            pending.clear();
          }
        if (!pending.empty())
          lines.emplace_back(first, dealii::Utilities::trim(pending));
        return lines;
      }

      /** The first word of @p line and the rest (trimmed). */
      std::pair<std::string, std::string>
      split_keyword(const std::string &line)
      {
        const auto space = line.find_first_of(" \t");
        if (space == std::string::npos)
          return {line, ""};
        return {line.substr(0, space), dealii::Utilities::trim(line.substr(space + 1))};
      }

      void
      check_file(const std::string &filename, std::vector<std::string> &chain)
      {
        const std::string me = identity(filename);
        for (const auto &outer : chain)
          if (outer == me)
            {
              std::string loop;
              for (const auto &file : chain)
                loop += file + " -> ";
              throw InputError("include",
                               filename,
                               "a file that does not include itself, directly or through "
                               "others (the includes loop: "
                                 + loop + me + ")");
            }
        std::ifstream in(filename);
        if (!in)
          return; // deal.II names a file it cannot open
        if (in.peek() == 0xEF)
          {
            char bom[3] = {0, 0, 0};
            in.read(bom, 3);
            if (static_cast<unsigned char>(bom[1]) == 0xBB
                && static_cast<unsigned char>(bom[2]) == 0xBF)
              throw InputError("(line 1 of " + filename + ")",
                               "a UTF-8 byte-order mark",
                               "a scene file without a byte-order mark: save it as UTF-8 "
                               "without BOM (or as plain ASCII)");
            in.seekg(0);
          }
        chain.push_back(me);
        // Where each parameter was set in this file: its path -> the line.
        std::map<std::string, unsigned int> set_at;
        std::vector<std::string>            subsections;
        for (const auto &[number, line] : logical_lines(in))
          {
            const auto [keyword, rest] = split_keyword(line);
            if (keyword == "subsection")
              subsections.push_back(rest);
            else if (keyword == "end" && !subsections.empty())
              subsections.pop_back();
            else if (keyword == "set")
              {
                const auto  equal = rest.find('=');
                std::string path;
                for (const auto &s : subsections)
                  path += s + "/";
                path += dealii::Utilities::trim(rest.substr(0, equal));
                const auto [where, first_time] = set_at.emplace(path, number);
                if (!first_time)
                  throw InputError(path,
                                   "set on lines " + std::to_string(where->second) + " and "
                                     + std::to_string(number) + " of " + filename,
                                   "one value per parameter in a file (to override a "
                                   "value, include the file and set it again after the "
                                   "include, or use --set)");
              }
            else if (keyword == "include")
              check_file(rest, chain);
          }
        chain.pop_back();
      }
    } // namespace



    void
    check_scene_file(const std::string &filename)
    {
      std::vector<std::string> chain;
      check_file(filename, chain);
    }
  } // namespace core
} // namespace slidewave
