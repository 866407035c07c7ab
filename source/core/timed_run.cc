#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <exception>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/timed_run.h>

namespace slidewave
{
  bool
  run_with_timer(const bool test_mode, const std::function<bool(dealii::TimerOutput &)> &time_loop)
  {
    const bool writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    dealii::ConditionalOStream timer_out(std::cout, writer && !test_mode);
    std::exception_ptr         failure;
    bool                       within = false;
    {
      // Each rank times its own sections (a timer on MPI_COMM_WORLD would put a barrier
      // at the start and the end of every section, a few per time step); the summary is
      // rank 0's, and with several ranks the spread over the ranks is printed before it.
      dealii::TimerOutput timer(timer_out,
                                test_mode ? dealii::TimerOutput::never :
                                            dealii::TimerOutput::summary,
                                dealii::TimerOutput::wall_times);
      try
        {
          within = time_loop(timer);
          // Each section's wall time over the ranks (min, average, max, and which rank):
          // where one rank waits for another. Collective, so only after a loop that ended
          // normally on every rank.
          if (!test_mode && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
            timer.print_wall_time_statistics(MPI_COMM_WORLD);
        }
      catch (const InputError &)
        {
          // Bad input found while setting up: nothing ran, no timings to show.
          timer.disable_output();
          failure = std::current_exception();
        }
      catch (...)
        {
          failure = std::current_exception();
        }
    }
    if (failure)
      std::rethrow_exception(failure);
    return within;
  }
} // namespace slidewave
