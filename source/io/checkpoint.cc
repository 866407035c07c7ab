#include <algorithm>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/io/checkpoint.h>
#include <slidewave/io/checkpoint_manifest.h>
#include <sstream>

namespace slidewave
{
  namespace io
  {
    namespace
    {
      /** The first words of scene.txt: the format of the checkpoint's data (format 2: the
       *  cells carry their partition first, BackgroundGrid::save; format 3: granular water
       *  keeps the solid's flux of the step's start, and the water's volume is the integral
       *  of n phi in porous solids; format 4: granular water keeps the water's balance,
       *  its initial volume and largest drift). */
      constexpr const char *format_tag = "checkpoint format 4: ";
    } // namespace



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

      /** The damage an InputError of a CheckpointRecord describes, with the folder's path
       *  taken out of the file names: "'record.txt' is damaged: ...". */
      std::string
      damage(const InputError &error, const fs::path &folder)
      {
        std::string       text   = error.allowed;
        const std::string opener = "a readable checkpoint (";
        if (text.compare(0, opener.size(), opener) == 0 && text.back() == ')')
          text = text.substr(opener.size(), text.size() - opener.size() - 1);
        const std::string prefix = (folder / "").string();
        for (auto at = text.find(prefix); at != std::string::npos; at = text.find(prefix))
          text.erase(at, prefix.size());
        return text;
      }

      /** What is wrong with the checkpoint in @p folder (empty: it can be used): its files
       *  against its manifest, then its record (readable, and what @p check_record says).
       *  Nothing of it has been read by deal.II or p4est yet (one process). */
      std::string
      problem_of(const fs::path                                             &folder,
                 const std::function<std::string(const CheckpointRecord &)> &check_record)
      {
        if (!fs::is_directory(folder))
          return "it does not exist";
        try
          {
            std::string problem = CheckpointManifest::check(folder.string());
            if (!problem.empty())
              return problem;
            for (const std::string name : {"scene.txt", "record.txt"})
              if (!fs::is_regular_file(folder / name))
                return "'" + name + "' is missing";
            CheckpointRecord record;
            record.read((folder / "record.txt").string());
            return check_record(record);
          }
        catch (const InputError &error)
          {
            return damage(error, folder);
          }
        catch (const std::exception &error)
          {
            return error.what();
          }
      }
    } // namespace



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
      // Every rank has written its part of the binary data before rank 0 lists the files.
      MPI_Barrier(MPI_COMM_WORLD);
      if (is_writer())
        {
          const fs::path directory = output_directory, tmp = temporary_path(),
                         latest   = directory / "checkpoint",
                         previous = directory / "checkpoint.previous";
          {
            std::ofstream out(tmp / "scene.txt");
            out << format_tag << signature << '\n';
          }
          record.write((tmp / "record.txt").string());
          for (const auto &name : growing_files)
            if (fs::exists(directory / name))
              fs::copy_file(directory / name,
                            tmp / copy_name(name),
                            fs::copy_options::overwrite_existing);
          // Last, when every file is complete: their sizes and checksums.
          CheckpointManifest::write(tmp.string(),
                                    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
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
    CheckpointDirectory::choose(
      const std::function<std::string(const CheckpointRecord &)> &check_record) const
    {
      const fs::path directory = output_directory, latest = directory / "checkpoint",
                     previous = directory / "checkpoint.previous";
      // Rank 0 checks, every rank takes its verdict: all read the same checkpoint, and
      // none has read anything of a damaged one. The verdict: the folder to read (empty:
      // none), what to print and, when there is none, why.
      std::vector<std::string> verdict(3);
      // Rank 0 must reach the broadcast whatever happens, or the others wait forever.
      if (is_writer())
        try
          {
            const std::string newest = problem_of(latest, check_record);
            if (newest.empty())
              verdict[0] = latest.string();
            else if (!fs::exists(latest) && !fs::exists(previous))
              verdict[2] = "a checkpoint in '" + latest.string()
                           + "' (there is none: run the scene with checkpoints first)";
            else
              {
                const std::string older = problem_of(previous, check_record);
                if (!older.empty())
                  verdict[2] = "an intact checkpoint; '" + latest.string() + "': " + newest + "; '"
                               + previous.string() + "': " + older;
                else
                  {
                    // A missing newest one is what a run killed between the two renames
                    // leaves: the previous one is taken silently.
                    verdict[0] = previous.string();
                    if (fs::exists(latest))
                      verdict[1] = "slidewave: the checkpoint '" + latest.string()
                                   + "' is damaged: " + newest + "; resuming from '"
                                   + previous.string() + "'";
                  }
              }
          }
        catch (const std::exception &error)
          {
            verdict = {"", "", std::string("a checkpoint that can be checked: ") + error.what()};
          }
      verdict = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, verdict, 0);
      if (!verdict[2].empty())
        throw InputError(resume_parameter, "true", verdict[2]);
      if (is_writer() && !verdict[1].empty())
        std::cerr << verdict[1] << std::endl;
      return verdict[0];
    }



    std::string
    CheckpointDirectory::read(
      const std::string                                          &signature,
      CheckpointRecord                                           &record,
      const std::vector<std::string>                             &growing_files,
      const std::function<std::string(const CheckpointRecord &)> &check_record) const
    {
      const fs::path directory = output_directory;
      const fs::path source    = choose(check_record);
      std::ifstream  in(source / "scene.txt");
      std::string    written_by;
      std::getline(in, written_by);
      if (written_by.rfind(format_tag, 0) != 0)
        throw InputError(resume_parameter,
                         "true",
                         "a checkpoint in this version's format ('" + std::string(format_tag)
                           + "'); the one in '" + source.string()
                           + "' was written by an older version in another format (run the "
                             "scene from its start)");
      written_by.erase(0, std::string(format_tag).size());
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
