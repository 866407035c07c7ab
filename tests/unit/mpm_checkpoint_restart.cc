// Checkpoint and restart of a material point scene (tests/common/restart_column.prm: GIMP,
// Drucker-Prager, adaptive grid, checkpoints every 150 steps):
// 1. the uninterrupted run prints its statistics rows and leaves checkpoints at steps 300
//    (checkpoint) and 150 (checkpoint.previous);
// 2. --resume continues from step 300: its rows must equal the uninterrupted run's rows
//    after step 300 character for character (the restart is exact: the grid, every point
//    property, the time, the step counters and the lost mass are restored; dt is recomputed
//    from that state);
// 3. without the newest checkpoint (a run killed while writing it leaves checkpoint.tmp
//    and the previous one), --resume falls back to checkpoint.previous: rows after step 150
//    equal, again exactly;
// 4. a scene with another grid is refused (exit status 1, message naming both scenes);
// 5. --resume with no checkpoint at all is refused (exit status 1).
// The mpirun=2 variant does all of this on two ranks.
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <slidewave/app/application.h>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  struct Result
  {
    int                      status;
    std::vector<std::string> rows;
    std::string              error;
  };

  /** Runs the application with std::cout captured (test-mode rows go there). */
  Result
  run(const std::vector<std::string> &arguments)
  {
    std::ostringstream captured, out, err;
    std::streambuf    *old    = std::cout.rdbuf(captured.rdbuf());
    const int          status = slidewave::run_application(arguments, out, err);
    std::cout.rdbuf(old);
    Result             result{status, {}, err.str()};
    std::istringstream lines(captured.str());
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("time=", 0) == 0)
        result.rows.push_back(line);
    return result;
  }

  /** The message without the machine's source path. */
  std::string
  without_path(std::string message)
  {
    const std::string directory = SOURCE_DIR "/../common/";
    for (auto at = message.find(directory); at != std::string::npos; at = message.find(directory))
      message.erase(at, directory.size());
    return message;
  }



  unsigned int
  step_of(const std::string &row)
  {
    return std::stoul(row.substr(row.find("step=") + 5));
  }

  /** Rows of @p full after step @p after, compared with @p resumed. */
  bool
  same_tail(const std::vector<std::string> &full,
            const std::vector<std::string> &resumed,
            const unsigned int              after)
  {
    std::vector<std::string> tail;
    for (const auto &row : full)
      if (step_of(row) > after)
        tail.push_back(row);
    return !resumed.empty() && tail == resumed;
  }
} // namespace



int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool        writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string scene  = SOURCE_DIR "/../common/restart_column.prm";
  const std::string output = "output-restart";
  if (writer)
    std::filesystem::remove_all(output);
  MPI_Barrier(MPI_COMM_WORLD);
  const std::string directory = "Output directory=" + output;

  const Result full    = run({"--set", directory, scene});
  const Result resumed = run({"--set", directory, "--resume", scene});

  // A run killed while writing its newest checkpoint: only the previous one is intact.
  if (writer)
    {
      std::filesystem::rename(output + "/checkpoint", output + "/checkpoint.tmp");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const Result from_previous = run({"--set", directory, "--resume", scene});

  const Result other_grid
    = run({"--set", directory, "--set", "Material points/Grid/Cell size=0.02", "--resume", scene});
  const Result nothing = run({"--set", "Output directory=output-restart-empty", "--resume", scene});

  if (writer)
    {
      std::cout << "uninterrupted run: status " << full.status << ", " << full.rows.size()
                << " rows, last at step " << step_of(full.rows.back()) << std::endl;
      std::cout << "resumed from step 300: status " << resumed.status << ", " << resumed.rows.size()
                << " rows, equal to the uninterrupted ones: "
                << (same_tail(full.rows, resumed.rows, 300) ? "yes" : "no") << std::endl;
      std::cout << "resumed from checkpoint.previous (step 150): status " << from_previous.status
                << ", " << from_previous.rows.size() << " rows, equal to the uninterrupted ones: "
                << (same_tail(full.rows, from_previous.rows, 150) ? "yes" : "no") << std::endl;
      std::cout << "another grid: status " << other_grid.status << std::endl
                << without_path(other_grid.error);
      std::cout << "no checkpoint: status " << nothing.status << std::endl
                << without_path(nothing.error);
      const std::string last = full.rows.back();
      std::cout << "last row: " << last.substr(0, last.find(" load_imbalance")) << std::endl;
    }
  return 0;
}
