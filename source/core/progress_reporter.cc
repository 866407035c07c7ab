#include <cstdio>
#include <slidewave/core/progress_reporter.h>

namespace slidewave
{
  ProgressReporter::ProgressReporter(std::ostream *out,
                                     const double  start_time,
                                     const double  end_time,
                                     const double  seconds_between_lines)
    : out(out)
    , start_time(start_time)
    , end_time(end_time)
    , seconds_between_lines(seconds_between_lines)
    , wall_start(std::chrono::steady_clock::now())
    , last_line(wall_start)
  {
  }



  void
  ProgressReporter::report(const unsigned int step,
                           const double       time,
                           const double       dt,
                           const bool         force)
  {
    if (out == nullptr)
      return;
    const auto   now   = std::chrono::steady_clock::now();
    const double since = std::chrono::duration<double>(now - last_line).count();
    if (!force && step > 1 && since < seconds_between_lines)
      return;
    last_line = now;

    const double elapsed  = std::chrono::duration<double>(now - wall_start).count();
    const double fraction = (time - start_time) / (end_time - start_time);
    const double eta      = fraction > 0. ? elapsed * (1. - fraction) / fraction : 0.;

    char line[160];
    std::snprintf(line,
                  sizeof(line),
                  "step %8u  t = %.6e s  dt = %.3e s  %5.1f%%  elapsed %.1f s  ETA %.1f s",
                  step,
                  time,
                  dt,
                  100. * fraction,
                  elapsed,
                  eta);
    *out << line << std::endl;
  }
} // namespace slidewave
