#include <algorithm>
#include <cmath>
#include <slidewave/coupling/monotone_cubic.h>

namespace slidewave
{
  namespace coupling
  {
    void
    MonotoneCubic::reinit(const std::vector<double> &x, const std::vector<double> &y)
    {
      xs                  = x;
      ys                  = y;
      const std::size_t n = xs.size();
      slopes.assign(n, 0.);
      if (n < 2)
        return;
      const auto secant
        = [&](const std::size_t k) { return (ys[k + 1] - ys[k]) / (xs[k + 1] - xs[k]); };
      // Interior: zero at extrema and where the data is flat, otherwise the weighted
      // harmonic mean of the neighbouring secants (never steeper than 3 times either).
      for (std::size_t k = 1; k + 1 < n; ++k)
        {
          const double d0 = secant(k - 1), d1 = secant(k);
          if (d0 * d1 <= 0.)
            continue;
          const double h0 = xs[k] - xs[k - 1], h1 = xs[k + 1] - xs[k];
          const double w0 = 2. * h1 + h0, w1 = h1 + 2. * h0;
          slopes[k] = (w0 + w1) / (w0 / d0 + w1 / d1);
        }
      // Ends: the one-sided three-point formula, limited so the end interval stays
      // monotone.
      const auto end_slope
        = [](const double h0, const double h1, const double d0, const double d1) {
            double s = ((2. * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
            if (s * d0 <= 0.)
              s = 0.;
            else if (d0 * d1 <= 0. && std::abs(s) > 3. * std::abs(d0))
              s = 3. * d0;
            return s;
          };
      if (n == 2)
        slopes[0] = slopes[1] = secant(0);
      else
        {
          slopes[0] = end_slope(xs[1] - xs[0], xs[2] - xs[1], secant(0), secant(1));
          slopes[n - 1]
            = end_slope(xs[n - 1] - xs[n - 2], xs[n - 2] - xs[n - 3], secant(n - 2), secant(n - 3));
        }
    }



    double
    MonotoneCubic::value(const double x) const
    {
      if (xs.empty())
        return 0.;
      if (x <= xs.front())
        return ys.front();
      if (x >= xs.back())
        return ys.back();
      const std::size_t k
        = static_cast<std::size_t>(std::upper_bound(xs.begin(), xs.end(), x) - xs.begin()) - 1;
      const double h  = xs[k + 1] - xs[k];
      const double t  = (x - xs[k]) / h;
      const double t2 = t * t, t3 = t2 * t;
      return (2. * t3 - 3. * t2 + 1.) * ys[k] + (t3 - 2. * t2 + t) * h * slopes[k]
             + (-2. * t3 + 3. * t2) * ys[k + 1] + (t3 - t2) * h * slopes[k + 1];
    }
  } // namespace coupling
} // namespace slidewave
