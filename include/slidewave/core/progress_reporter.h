#ifndef slidewave_core_progress_reporter_h
#define slidewave_core_progress_reporter_h

#include <chrono>
#include <ostream>

namespace slidewave
{
  /**
   * The console progress line on rank 0: step, time, dt, percent done and the estimated
   * time to completion. It prints at most once every few seconds of wall time (and at the
   * first and last step), so a run of a million steps does not flood the terminal.
   */
  class ProgressReporter
  {
  public:
    /** @p out null disables reporting (other ranks, test mode). */
    ProgressReporter(std::ostream *out,
                     double        start_time,
                     double        end_time,
                     double        seconds_between_lines = 2.);

    void
    report(unsigned int step, double time, double dt, bool force = false);

  private:
    std::ostream                         *out;
    double                                start_time;
    double                                end_time;
    double                                seconds_between_lines;
    std::chrono::steady_clock::time_point wall_start;
    std::chrono::steady_clock::time_point last_line;
  };
} // namespace slidewave

#endif
