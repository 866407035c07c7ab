#include <algorithm>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/io/checkpoint.h>
#include <sstream>

namespace slidewave
{
  namespace io
  {
    namespace
    {
      namespace fs = std::filesystem;

      const std::string resume_parameter = "Checkpoint/Resume";

      bool
      is_writer()
      {
        return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      }

      /** A file name inside the checkpoint for an output file (a/b.csv -> a_b.csv). */
      std::string
      copy_name(std::string relative)
      {
        for (char &c : relative)
          if (c == '/')
            c = '_';
        return relative;
      }
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
      return static_cast<unsigned int>(get(name));
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
      if (!out)
        throw std::runtime_error("cannot write " + name);
    }



    void
    CheckpointRecord::read(const std::string &name)
    {
      file_name = name;
      numbers.clear();
      texts.clear();
      std::ifstream in(name);
      const auto    damaged = [&]() {
        return InputError(resume_parameter,
                          "true",
                          "a readable checkpoint ('" + name + "' is damaged)");
      };
      for (std::string line; std::getline(in, line);)
        {
          if (line.empty())
            continue;
          const auto space = line.find(' ');
          if (space == std::string::npos)
            throw damaged();
          const std::string key = line.substr(0, space);
          if (line.compare(space, 3, " = ") == 0)
            {
              texts[key] = line.substr(space + 3);
              continue;
            }
          std::istringstream values(line.substr(space + 1));
          std::size_t        n = 0;
          if (!(values >> n))
            throw damaged();
          std::vector<double> &entry = numbers[key];
          entry.resize(n);
          for (double &v : entry)
            {
              std::string word;
              if (!(values >> word))
                throw damaged();
              char *end = nullptr;
              v         = std::strtod(word.c_str(), &end);
              if (end == word.c_str() || *end != '\0')
                throw damaged();
            }
        }
    }



    CheckpointDirectory::CheckpointDirectory(const std::string &output_directory)
      : output_directory(output_directory)
    {
    }



    std::string
    CheckpointDirectory::temporary_path() const
    {
      return (fs::path(output_directory) / "checkpoint.tmp").string();
    }



    std::string
    CheckpointDirectory::data_prefix(const std::string &checkpoint_path)
    {
      return (fs::path(checkpoint_path) / "state").string();
    }



    void
    CheckpointDirectory::begin_write() const
    {
      if (is_writer())
        {
          fs::remove_all(temporary_path());
          fs::create_directories(temporary_path());
        }
      MPI_Barrier(MPI_COMM_WORLD);
    }



    void
    CheckpointDirectory::finish_write(const std::string              &signature,
                                      const CheckpointRecord         &record,
                                      const std::vector<std::string> &growing_files) const
    {
      if (is_writer())
        {
          const fs::path directory = output_directory, tmp = temporary_path(),
                         latest   = directory / "checkpoint",
                         previous = directory / "checkpoint.previous";
          {
            std::ofstream out(tmp / "scene.txt");
            out << signature << '\n';
          }
          record.write((tmp / "record.txt").string());
          for (const auto &name : growing_files)
            if (fs::exists(directory / name))
              fs::copy_file(directory / name,
                            tmp / copy_name(name),
                            fs::copy_options::overwrite_existing);
          if (fs::exists(latest))
            {
              fs::remove_all(previous);
              fs::rename(latest, previous);
            }
          fs::rename(tmp, latest);
        }
      MPI_Barrier(MPI_COMM_WORLD);
    }



    std::string
    CheckpointDirectory::read(const std::string              &signature,
                              CheckpointRecord               &record,
                              const std::vector<std::string> &growing_files) const
    {
      const fs::path directory = output_directory;
      fs::path       source    = directory / "checkpoint";
      if (!fs::exists(source / "record.txt"))
        source = directory / "checkpoint.previous";
      if (!fs::exists(source / "record.txt"))
        throw InputError(resume_parameter,
                         "true",
                         "a checkpoint in '" + (directory / "checkpoint").string()
                           + "' (there is none: run the scene with checkpoints first)");
      std::ifstream in(source / "scene.txt");
      std::string   written_by;
      std::getline(in, written_by);
      if (written_by != signature)
        throw InputError(resume_parameter,
                         "true",
                         "a checkpoint written by this scene; the one in '" + source.string()
                           + "' is of a different scene (" + written_by
                           + "; this scene: " + signature + ")");
      record.read((source / "record.txt").string());

      // Every rank has read the record; only then does rank 0 put the files back.
      MPI_Barrier(MPI_COMM_WORLD);
      if (is_writer())
        for (const auto &name : growing_files)
          if (fs::exists(source / copy_name(name)))
            fs::copy_file(source / copy_name(name),
                          directory / name,
                          fs::copy_options::overwrite_existing);
      MPI_Barrier(MPI_COMM_WORLD);
      return data_prefix(source.string());
    }
  } // namespace io
} // namespace slidewave
