#include <algorithm>
#include <cmath>
#include <slidewave/fluid/standing_wave.h>

namespace slidewave
{
  namespace fluid
  {
    StandingWaveResult
    analyse_standing_wave(const std::vector<std::pair<double, double>> &eta,
                          const double                                  depth,
                          const double                                  length,
                          const double                                  g)
    {
      StandingWaveResult result;
      const double       k     = M_PI / length;
      const double       omega = std::sqrt(g * k * std::tanh(k * depth));
      result.exact_period      = 2. * M_PI / omega;

      std::vector<double> crossings;
      std::vector<double> extremes{0.}; // the largest |eta - d| of each half period
      for (std::size_t i = 1; i < eta.size(); ++i)
        {
          const double a = eta[i - 1].second - depth, b = eta[i].second - depth;
          extremes.back() = std::max(extremes.back(), std::abs(b));
          if ((a > 0.) != (b > 0.) && a != b)
            {
              crossings.push_back(eta[i - 1].first
                                  + a / (a - b) * (eta[i].first - eta[i - 1].first));
              extremes.push_back(0.);
            }
        }
      result.n_crossings = crossings.size();
      if (crossings.size() >= 3)
        {
          result.period = 2. * (crossings.back() - crossings.front()) / (crossings.size() - 1.);
          result.period_error = (result.period - result.exact_period) / result.exact_period;
          // The first and the last complete half periods (between crossings).
          result.amplitude_ratio = extremes[extremes.size() - 2] / extremes[1];
        }
      return result;
    }
  } // namespace fluid
} // namespace slidewave
