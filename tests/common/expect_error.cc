// Test driver for scenes that SlideWave must refuse (tests/bad_input): runs the application
// on the scene exactly as `slidewave SCENE.prm` would, prints what the user would see on the
// error stream (with the scene's directory removed, so the output does not depend on where
// the sources are) and the exit status. It succeeds only when the application failed: the
// test harness then compares the printed message and status with the expected output, so a
// scene that is accepted fails at the run stage and a changed message fails at the diff.
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iostream>
#include <slidewave/app/application.h>
#include <sstream>

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           arguments(argv + 1, argv + argc);

  std::ostringstream out, err;
  const int          status = slidewave::run_application(arguments, out, err);

  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::string message = err.str();
      for (const auto &argument : arguments)
        {
          const std::string directory
            = std::filesystem::path(argument).parent_path().string() + "/";
          if (directory.size() > 1)
            for (auto at = message.find(directory); at != std::string::npos;
                 at      = message.find(directory))
              message.erase(at, directory.size());
        }
      std::cout << message << "exit status: " << status << std::endl;
    }
  return status == 0 ? 1 : 0;
}
