#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/io/checkpoint_record.h>
#include <sstream>

namespace slidewave
{
  namespace io
  {
    namespace
    {
      const std::string resume_parameter = "Checkpoint/Resume";
    } // namespace



    template <typename Value>
    const Value &
    CheckpointRecord::find_entry(const std::map<std::string, Value> &entries,
                                 const std::string                  &name) const
    {
      const auto entry = entries.find(name);
      if (entry == entries.end())
        throw InputError(resume_parameter,
                         "true",
                         "a readable checkpoint ('" + file_name + "' is damaged: it has no '" + name
                           + "')");
      return entry->second;
    }



    void
    CheckpointRecord::put(const std::string &name, const double value)
    {
      numbers[name] = {value};
    }



    void
    CheckpointRecord::put(const std::string &name, const std::vector<double> &values)
    {
      numbers[name] = values;
    }



    void
    CheckpointRecord::put_text(const std::string &name, const std::string &text)
    {
      texts[name] = text;
    }



    const std::vector<double> &
    CheckpointRecord::get_vector(const std::string &name) const
    {
      return find_entry(numbers, name);
    }



    void
    CheckpointRecord::put_files(const std::string                                 &name,
                                const std::vector<std::pair<double, std::string>> &files)
    {
      std::vector<double> times;
      std::string         names;
      for (const auto &[time, file] : files)
        {
          times.push_back(time);
          names += (names.empty() ? "" : "|") + file;
        }
      put(name + "/times", times);
      put_text(name + "/names", names);
    }



    std::vector<std::pair<double, std::string>>
    CheckpointRecord::get_files(const std::string &name) const
    {
      const auto                                 &times = get_vector(name + "/times");
      const std::string                          &names = get_text(name + "/names");
      std::vector<std::pair<double, std::string>> files;
      std::size_t                                 begin = 0;
      for (const double time : times)
        {
          const std::size_t end = std::min(names.find('|', begin), names.size());
          if (begin > names.size())
            throw InputError(resume_parameter,
                             "true",
                             "a readable checkpoint ('" + file_name + "' is damaged: '" + name
                               + "' has fewer names than times)");
          files.emplace_back(time, names.substr(begin, end - begin));
          begin = end + 1;
        }
      return files;
    }



    double
    CheckpointRecord::get(const std::string &name) const
    {
      const auto &values = get_vector(name);
      if (values.size() != 1)
        throw InputError(resume_parameter,
                         "true",
                         "a readable checkpoint ('" + file_name + "' is damaged: '" + name
                           + "' is not one number)");
      return values[0];
    }



    unsigned int
    CheckpointRecord::get_unsigned(const std::string &name) const
    {
      const double value = get(name);
      if (!(value >= 0. && value <= std::numeric_limits<unsigned int>::max()
            && value == std::floor(value)))
        throw InputError(resume_parameter,
                         "true",
                         "a readable checkpoint ('" + file_name + "' is damaged: '" + name + "' is "
                           + to_string(value) + ", not a whole number from 0 to 4294967295)");
      return static_cast<unsigned int>(value);
    }



    const std::string &
    CheckpointRecord::get_text(const std::string &name) const
    {
      return find_entry(texts, name);
    }



    void
    CheckpointRecord::write(const std::string &name) const
    {
      std::ofstream out(name);
      char          number[32];
      for (const auto &[key, values] : numbers)
        {
          out << key << ' ' << values.size();
          for (const double v : values)
            {
              // %.17g gives back every double exactly (and inf, nan as words strtod reads).
              std::snprintf(number, sizeof(number), " %.17g", v);
              out << number;
            }
          out << '\n';
        }
      for (const auto &[key, text] : texts)
        out << key << " = " << text << '\n';
      out.close();
      require_written(out, name);
    }



    void
    CheckpointRecord::read(const std::string &name)
    {
      file_name = name;
      numbers.clear();
      texts.clear();
      std::ifstream in(name);
      if (!in)
        throw InputError(resume_parameter,
                         "true",
                         "a readable checkpoint ('" + name + "' cannot be read)");
      unsigned int line_number = 0;
      const auto   damaged     = [&](const std::string &what) {
        return InputError(resume_parameter,
                          "true",
                          "a readable checkpoint ('" + name + "' is damaged: line "
                            + std::to_string(line_number) + " " + what + ")");
      };
      for (std::string line; std::getline(in, line);)
        {
          ++line_number;
          if (line.empty())
            continue;
          const auto space = line.find(' ');
          if (space == std::string::npos)
            throw damaged("has a name and no value");
          const std::string key = line.substr(0, space);
          if (line.compare(space, 3, " = ") == 0)
            {
              texts[key] = line.substr(space + 3);
              continue;
            }
          // The count comes first; the words after it must be exactly that many finite
          // numbers (a count is never trusted to allocate before the words are there).
          std::istringstream       values(line.substr(space + 1));
          std::vector<std::string> words;
          for (std::string word; values >> word;)
            words.push_back(word);
          char                    *end = nullptr;
          const unsigned long long n
            = words.empty() ? 0 : std::strtoull(words[0].c_str(), &end, 10);
          if (words.empty() || end == words[0].c_str() || *end != '\0' || words[0][0] == '-')
            throw damaged("('" + key + "') does not start with a count of values");
          if (n != words.size() - 1)
            throw damaged("('" + key + "') announces " + words[0] + " values and holds "
                          + std::to_string(words.size() - 1));
          std::vector<double> entry(words.size() - 1);
          for (std::size_t i = 0; i < entry.size(); ++i)
            {
              const std::string &word = words[i + 1];
              entry[i]                = std::strtod(word.c_str(), &end);
              if (end == word.c_str() || *end != '\0')
                throw damaged("('" + key + "') holds '" + word + "', which is not a number");
              if (!std::isfinite(entry[i]))
                throw damaged("('" + key + "') holds '" + word
                              + "': every number of a checkpoint is finite");
            }
          numbers[key] = std::move(entry);
        }
    }
  } // namespace io
} // namespace slidewave
