#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/output_locations.h>
#include <unistd.h>

namespace slidewave
{
  namespace core
  {
    namespace fs = std::filesystem;

    std::string
    problem_writing_into(const std::string &path)
    {
      // A file where a folder must be: the path itself or one of its parents.
      std::error_code error;
      for (fs::path p = path; !p.empty(); p = p.parent_path())
        {
          if (fs::exists(p, error) && !fs::is_directory(p, error))
            return "'" + p.string() + "' is a file, not a directory";
          if (p == p.parent_path())
            break;
        }
      fs::create_directories(path, error);
      if (error || !fs::is_directory(path, error))
        return "'" + path + "' cannot be created ("
               + (error ? error.message() : std::string("not a directory")) + ")";
      if (access(path.c_str(), W_OK | X_OK) != 0)
        return "'" + path + "' is not writable";
      const fs::path probe = fs::path(path) / ".slidewave-write-test";
      bool           written;
      {
        std::ofstream test(probe);
        test << "probe\n";
        test.close();
        written = !test.fail();
      }
      fs::remove(probe, error);
      if (!written)
        return "no file can be written in '" + path + "'";
      return "";
    }



    void
    prepare_output_locations(const std::string &directory, const std::vector<OutputFolder> &folders)
    {
      std::string problem;
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          // Rank 0 must reach the broadcast whatever happens, or the others wait forever.
          try
            {
              problem = problem_writing_into(directory);
              for (const auto &folder : folders)
                if (problem.empty())
                  {
                    problem = problem_writing_into((fs::path(directory) / folder.folder).string());
                    if (!problem.empty())
                      problem += " (the folder of " + folder.what + ")";
                  }
            }
          catch (const std::exception &e)
            {
              problem = e.what();
            }
        }
      problem = dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, problem, 0);
      if (!problem.empty())
        throw InputError("Output directory",
                         directory,
                         "a directory where the scene can write (created if missing) and "
                         "its folders: "
                           + problem);
    }
  } // namespace core
} // namespace slidewave
