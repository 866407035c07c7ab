// The `slidewave` executable: MPI set-up around the application in the library.
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <exception>
#include <iostream>
#include <new>
#include <slidewave/app/application.h>

int
main(int argc, char *argv[])
{
  // The application reports every error of a scene (input, run, output, memory, file
  // system, deal.II) with what to change; what reaches this point escaped it, and must
  // still say what happened and what to do.
  const char *report = " (please report it with the scene file and the command line)";
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const std::vector<std::string>           arguments(argv + 1, argv + argc);
      return slidewave::run_application(arguments, std::cout, std::cerr);
    }
  catch (const std::bad_alloc &)
    {
      std::cerr << "slidewave: out of memory: the scene needs more memory than this machine "
                   "could give; 'slidewave --validate SCENE.prm' prints its memory estimate "
                   "(doc/stability.md, 'Memory estimate'): make the grid coarser or smaller, "
                   "use fewer points per cell, or run on more nodes\n";
      return 4;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "slidewave: internal error: deal.II: " << e.get_exc_name() << ": " << e.what()
                << report << std::endl;
      return 4;
    }
  catch (const std::exception &e)
    {
      const std::string what = e.what();
      std::cerr << "slidewave: internal error: "
                << (what.empty() ? std::string("an exception without a message") : what) << report
                << std::endl;
      return 4;
    }
  catch (...)
    {
      std::cerr << "slidewave: internal error: an exception of unknown type" << report << std::endl;
      return 4;
    }
}
