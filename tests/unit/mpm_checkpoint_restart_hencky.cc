// Checkpoint and restart of a material point scene of the finite-strain model
// (tests/common/restart_column.prm with 'Model = hencky drucker prager': its points carry
// b^e, four properties more than the small-strain scene's):
// 1. the uninterrupted run leaves checkpoints at steps 300 and 150;
// 2. --resume continues from step 300: its rows equal the uninterrupted run's rows after
//    step 300 character for character (b^e is restored with the other point properties:
//    a point restarted from b^e = I, or from its stress alone, would move otherwise);
// 3. the small-strain scene (the same materials' names, no b^e) refuses the finite-strain
//    checkpoint (exit status 1, the two signatures in the message), and the finite-strain
//    scene refuses the small-strain one.
// The mpirun=2 variant does all of this on two ranks.
#include <deal.II/base/mpi.h>
#include <filesystem>
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
  run(std::vector<std::string> arguments)
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
  const std::string output = "output-restart-hencky", small = "output-restart-small-strain";
  if (writer)
    {
      std::filesystem::remove_all(output);
      std::filesystem::remove_all(small);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  const std::vector<std::string> hencky{"--set",
                                        "Material points/Material 1/Model=hencky drucker prager",
                                        "--set",
                                        "Material points/Material 1/Tension cutoff=0"};
  const auto with = [](std::vector<std::string> a, const std::vector<std::string> &b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };

  const Result full = run(with(with({"--set", "Output directory=" + output}, hencky), {scene}));
  const Result resumed
    = run(with(with({"--set", "Output directory=" + output}, hencky), {"--resume", scene}));
  const Result small_strain_resumes
    = run({"--set", "Output directory=" + output, "--resume", scene});
  const Result small_strain_run = run({"--set", "Output directory=" + small, scene});
  const Result hencky_resumes_small_strain
    = run(with(with({"--set", "Output directory=" + small}, hencky), {"--resume", scene}));

  if (writer)
    {
      std::cout << "uninterrupted run: status " << full.status << ", " << full.rows.size()
                << " rows, last at step " << step_of(full.rows.back()) << std::endl;
      std::cout << "resumed from step 300: status " << resumed.status << ", " << resumed.rows.size()
                << " rows, equal to the uninterrupted ones: "
                << (same_tail(full.rows, resumed.rows, 300) ? "yes" : "no") << std::endl;
      std::cout << "small-strain scene on the finite-strain checkpoint: status "
                << small_strain_resumes.status << std::endl
                << without_path(small_strain_resumes.error);
      std::cout << "small-strain run: status " << small_strain_run.status
                << "; finite-strain scene on its checkpoint: status "
                << hencky_resumes_small_strain.status << std::endl
                << without_path(hencky_resumes_small_strain.error);
      const std::string last = full.rows.back();
      std::cout << "last row: " << last.substr(0, last.find(" load_imbalance")) << std::endl;
    }
  return 0;
}
