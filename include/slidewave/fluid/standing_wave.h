#ifndef slidewave_fluid_standing_wave_h
#define slidewave_fluid_standing_wave_h

#include <complex>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /** A standing wave's period and decay measured at a wall against linear theory. */
    struct StandingWaveResult
    {
      /** Zero crossings of eta - d seen (at least 3 give a period). */
      unsigned int n_crossings = 0;
      /** Measured and linear-theory period [s] (of the viscous wave), relative error of
       *  the measured one. */
      double period = 0., exact_period = 0., period_error = 0.;
      /** The last complete half period's extreme |eta - d| over the first one's, measured
       *  and by linear viscous theory over the same number of half periods. */
      double amplitude_ratio = 0., exact_amplitude_ratio = 1.;
      /** Measured decay rate over the theory's, minus 1: ln(ratio) / ln(exact ratio) - 1
       *  (meaningful where viscosity damps the wave by more than a few per cent). */
      double decay_error = 0.;
    };

    /**
     * The complex rate s (amplitude ~ e^{s t}) of the first sloshing mode, k = pi / L, of a
     * viscous liquid of depth @p depth and kinematic viscosity @p nu in a tank with free-slip
     * walls and bottom under a free surface (air neglected), by the exact linear theory
     * (Lamb 1932, Section 349, extended to finite depth): with m^2 = k^2 + s / nu,
     *
     *   s^2 + 2 nu k^2 s + g k tanh(kd) (1 - 2 k^2 / (m^2 + k^2))
     *       - 4 nu k^3 m s tanh(kd) coth(md) / (m^2 + k^2) = 0,
     *
     * solved by Newton's method from the inviscid s = i omega - 2 nu k^2 (whose real part is
     * the classical decay rate 2 nu k^2 of an irrotational wave). nu = 0 gives i omega,
     * omega^2 = g k tanh(kd).
     */
    std::complex<double>
    standing_wave_rate(double depth, double length, double g, double nu);

    /**
     * The period and decay of the first sloshing mode of a tank of length @p length and
     * still-water depth @p depth from the record @p eta (time, surface elevation at a side
     * wall), against standing_wave_rate() for the kinematic viscosity @p nu. The period is
     * twice the mean time between consecutive zero crossings of eta - d (linear
     * interpolation between steps).
     */
    StandingWaveResult
    analyse_standing_wave(const std::vector<std::pair<double, double>> &eta,
                          double                                        depth,
                          double                                        length,
                          double                                        g,
                          double                                        nu);
  } // namespace fluid
} // namespace slidewave

#endif
