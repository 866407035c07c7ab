#include <algorithm>
#include <cmath>
#include <limits>
#include <slidewave/fluid/martin_moyce.h>

namespace slidewave
{
  namespace fluid
  {
    const std::vector<std::pair<double, double>> &
    martin_moyce_front()
    {
      // Martin and Moyce (1952), n^2 = 2, a = 2.25 in: (T, Z).
      static const std::vector<std::pair<double, double>> data{{0., 1.},
                                                               {0.41, 1.11},
                                                               {0.84, 1.23},
                                                               {1.19, 1.44},
                                                               {1.43, 1.67},
                                                               {1.63, 1.89},
                                                               {1.82, 2.11},
                                                               {1.97, 2.33},
                                                               {2.2, 2.56},
                                                               {2.32, 2.78},
                                                               {2.5, 3.},
                                                               {2.64, 3.22},
                                                               {2.82, 3.44},
                                                               {2.96, 3.67}};
      return data;
    }



    namespace
    {
      /** Z_simulated at @p t by linear interpolation in the history: the initial front
       *  before it starts (a shifted comparison asks for negative times), NaN after it
       *  ends. */
      double
      simulated_front(const std::vector<std::pair<double, double>> &front,
                      const double                                  t,
                      const double                                  a)
      {
        if (front.empty() || t > front.back().first)
          return std::numeric_limits<double>::quiet_NaN();
        if (t <= front.front().first)
          return front.front().second / a;
        const auto after = std::lower_bound(front.begin(),
                                            front.end(),
                                            std::make_pair(t, -std::numeric_limits<double>::max()));
        if (after == front.begin())
          return after->second / a;
        const auto   before = after - 1;
        const double s      = (t - before->first) / (after->first - before->first);
        return ((1. - s) * before->second + s * after->second) / a;
      }

      /** RMS and largest difference with the simulated time shifted by @p shift. */
      std::pair<double, double>
      differences(const std::vector<std::pair<double, double>> &front,
                  const double                                  a,
                  const double                                  time_scale,
                  const double                                  shift,
                  unsigned int                                 &n)
      {
        double sum = 0., largest = 0.;
        n = 0;
        for (const auto &[T, Z] : martin_moyce_front())
          {
            const double z = simulated_front(front, (T - shift) / time_scale, a);
            if (!std::isfinite(z))
              continue;
            sum += (z - Z) * (z - Z);
            largest = std::max(largest, std::abs(z - Z));
            ++n;
          }
        return {n > 0 ? std::sqrt(sum / n) : 0., largest};
      }
    } // namespace



    MartinMoyceComparison
    compare_with_martin_moyce(const std::vector<std::pair<double, double>> &front,
                              const double                                  a,
                              const double                                  g)
    {
      const double          time_scale = std::sqrt(2. * g / a); // T = t time_scale
      MartinMoyceComparison result;
      const auto            plain = differences(front, a, time_scale, 0., result.n_points);
      result.rms_error            = plain.first;
      result.max_error            = plain.second;
      result.rms_error_shifted    = plain.first;
      for (unsigned int k = 1; k <= 100; ++k)
        {
          unsigned int n;
          const double shift = 0.005 * k;
          const auto   d     = differences(front, a, time_scale, shift, n);
          if (n == result.n_points && d.first < result.rms_error_shifted)
            {
              result.rms_error_shifted = d.first;
              result.best_shift        = shift;
            }
        }
      return result;
    }
  } // namespace fluid
} // namespace slidewave
