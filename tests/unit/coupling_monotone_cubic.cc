// The monotone cubic interpolation that rebuilds the water's bed from the soil surface
// (coupling::MonotoneCubic, Fritsch-Carlson / Fritsch-Butland): checked on
//  1. linear data on a non-uniform grid: reproduced exactly (the slopes are the secant),
//     error < 1e-13;
//  2. every data set: the interpolant passes through the samples (error < 1e-14) and is
//     C^1 (second-order one-sided differences at the samples agree to 1e-6, steps of 1e-6
//     of the intervals: truncation and round-off are both about 1e-9; a slope jump of a
//     C^0 interpolant would be of order 1);
//  3. a soil face (a step 1 -> 0 over one interval, flat on either side) and a corner
//     (flat, then a ramp): between two samples the interpolant stays within their values
//     (checked on 200 points per interval to 1e-14), so there is no bump above the
//     shoulder or dip below the toe (an unlimited cubic through a step overshoots by
//     several per cent of the step);
//  4. constant beyond the ends.
#include "unit_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <slidewave/coupling/monotone_cubic.h>
#include <vector>

using slidewave::coupling::MonotoneCubic;

using unit_check::check;

namespace
{

  void
  check_data(const char                *name,
             const std::vector<double> &x,
             const std::vector<double> &y,
             const bool                 monotone_pieces)
  {
    std::printf("%s (%zu samples)\n", name, x.size());
    MonotoneCubic f;
    f.reinit(x, y);
    double node_error = 0., kink = 0., overshoot = 0.;
    for (std::size_t k = 0; k < x.size(); ++k)
      {
        node_error = std::max(node_error, std::abs(f.value(x[k]) - y[k]));
        if (k > 0 && k + 1 < x.size())
          {
            // Second-order one-sided differences: their error is f''' d^2 ~ 1e-9 here,
            // the round-off 1e-16 / d ~ 1e-9.
            const double d = 1e-6 * (x[k + 1] - x[k - 1]);
            const double left
              = (3. * f.value(x[k]) - 4. * f.value(x[k] - d) + f.value(x[k] - 2. * d)) / (2. * d);
            const double right
              = (-3. * f.value(x[k]) + 4. * f.value(x[k] + d) - f.value(x[k] + 2. * d)) / (2. * d);
            kink = std::max(kink, std::abs(left - right));
          }
        if (k + 1 < x.size())
          for (unsigned int j = 1; j < 200; ++j)
            {
              const double v  = f.value(x[k] + (x[k + 1] - x[k]) * j / 200.);
              const double lo = std::min(y[k], y[k + 1]), hi = std::max(y[k], y[k + 1]);
              overshoot = std::max(overshoot, std::max(v - hi, lo - v));
            }
      }
    check(node_error < 1e-14, "passes through the samples (error < 1e-14)");
    check(kink < 1e-6, "C^1 at the samples (slope jump < 1e-6)");
    if (monotone_pieces)
      {
        std::printf("  largest excursion beyond the samples' range: %.1e\n",
                    std::max(overshoot, 0.));
        check(overshoot < 1e-14, "stays within each interval's values");
      }
    check(f.value(x.front() - 1.) == y.front() && f.value(x.back() + 1.) == y.back(),
          "constant beyond the ends");
  }
} // namespace

int
main()
{
  // 1. Linear data on a non-uniform grid.
  {
    std::vector<double> x{0., 0.1, 0.15, 0.4, 0.45, 1.}, y;
    for (const double v : x)
      y.push_back(0.3 - 2. * v);
    MonotoneCubic f;
    f.reinit(x, y);
    double error = 0.;
    for (unsigned int j = 0; j <= 1000; ++j)
      error = std::max(error, std::abs(f.value(j / 1000.) - (0.3 - 2. * j / 1000.)));
    std::printf("linear data\n");
    check(error < 1e-13, "reproduced exactly (error < 1e-13)");
    check_data("linear data", x, y, true);
  }
  // 3. A soil face: the column top at 1 m, the floor at 0 beyond x = 2.
  {
    std::vector<double> x, y;
    for (unsigned int c = 0; c < 16; ++c)
      {
        x.push_back(1.625 + 0.05 * c);
        y.push_back(x.back() < 2. ? 1. : 0.);
      }
    check_data("step (soil face)", x, y, true);
  }
  // A corner: flat shoulder, then a ramp down to the toe, then flat.
  {
    std::vector<double> x, y;
    for (unsigned int c = 0; c < 20; ++c)
      {
        x.push_back(0.05 * c);
        y.push_back(std::clamp(1. - 2. * (x.back() - 0.3), 0.2, 1.));
      }
    check_data("corner and ramp", x, y, true);
  }
  // A smooth, non-monotone surface (a mound): C^1 and through the samples.
  {
    std::vector<double> x, y;
    for (unsigned int c = 0; c < 30; ++c)
      {
        x.push_back(0.1 * c + 0.01 * std::sin(7. * c));
        y.push_back(0.5 + 0.3 * std::exp(-std::pow(x.back() - 1.5, 2)));
      }
    check_data("mound", x, y, false);
  }
  return unit_check::finish();
}
