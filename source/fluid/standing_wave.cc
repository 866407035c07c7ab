#include <algorithm>
#include <cmath>
#include <slidewave/fluid/standing_wave.h>

namespace slidewave
{
  namespace fluid
  {
    std::complex<double>
    standing_wave_rate(const double depth, const double length, const double g, const double nu)
    {
      using complex   = std::complex<double>;
      const double k  = M_PI / length;
      const double t  = std::tanh(k * depth);
      const double w0 = std::sqrt(g * k * t);
      if (nu <= 0.)
        return complex(0., w0);
      // The dispersion relation of the documentation above, f(s) = 0.
      const auto f = [&](const complex s) {
        const complex m  = std::sqrt(k * k + s / nu); // principal root: Re m > 0
        const complex m2 = m * m;
        return s * s + 2. * nu * k * k * s + g * k * t * (1. - 2. * k * k / (m2 + k * k))
               - 4. * nu * k * k * k * m * s * t / (std::tanh(m * depth) * (m2 + k * k));
      };
      complex s(-2. * nu * k * k, w0);
      for (unsigned int iteration = 0; iteration < 100; ++iteration)
        {
          const double  h          = 1e-7 * std::abs(s);
          const complex derivative = (f(s + h) - f(s - h)) / (2. * h);
          const complex step       = f(s) / derivative;
          s -= step;
          if (std::abs(step) < 1e-13 * std::abs(s))
            break;
        }
      return s;
    }



    StandingWaveResult
    analyse_standing_wave(const std::vector<std::pair<double, double>> &eta,
                          const double                                  depth,
                          const double                                  length,
                          const double                                  g,
                          const double                                  nu)
    {
      StandingWaveResult result;
      const auto         rate = standing_wave_rate(depth, length, g, nu);
      result.exact_period     = 2. * M_PI / rate.imag();

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
          // The first and the last complete half periods (between crossings), the
          // theory's decay over as many half periods.
          result.amplitude_ratio    = extremes[extremes.size() - 2] / extremes[1];
          const double half_periods = static_cast<double>(extremes.size()) - 3.;
          result.exact_amplitude_ratio
            = std::exp(rate.real() * half_periods * result.exact_period / 2.);
          result.decay_error
            = std::log(result.amplitude_ratio) / std::log(result.exact_amplitude_ratio) - 1.;
        }
      return result;
    }
  } // namespace fluid
} // namespace slidewave
