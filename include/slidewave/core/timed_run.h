#ifndef slidewave_core_timed_run_h
#define slidewave_core_timed_run_h

#include <deal.II/base/timer.h>
#include <functional>

namespace slidewave
{
  /**
   * Runs a scene's time loop with a TimerOutput that the loop fills and that prints its
   * summary on rank 0 at the end (never in test mode). Each rank times its own sections (no
   * barriers); the summary shows rank 0's times, and with several ranks a table of each
   * section's least, mean and largest time over the ranks comes before it (when the loop
   * ended normally on every rank). The timer lives in a block of its own
   * so that a run that fails still gets its summary and the error goes out after it; bad
   * input (InputError) found while setting up suppresses the summary, since nothing ran.
   * Returns what @p time_loop returns; rethrows what it threw.
   */
  bool
  run_with_timer(bool test_mode, const std::function<bool(dealii::TimerOutput &)> &time_loop);
} // namespace slidewave

#endif
