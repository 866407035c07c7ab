// The `slidewave` executable: MPI set-up around the application in the library.
#include <deal.II/base/mpi.h>
#include <exception>
#include <iostream>
#include <slidewave/app/application.h>

int
main(int argc, char *argv[])
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const std::vector<std::string>           arguments(argv + 1, argv + argc);
      return slidewave::run_application(arguments, std::cout, std::cerr);
    }
  catch (const std::exception &e)
    {
      std::cerr << "slidewave: internal error: " << e.what() << std::endl;
      return 4;
    }
}
