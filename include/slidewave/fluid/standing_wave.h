#ifndef slidewave_fluid_standing_wave_h
#define slidewave_fluid_standing_wave_h

#include <utility>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /** A standing wave's period measured at a wall against linear theory. */
    struct StandingWaveResult
    {
      /** Zero crossings of eta - d seen (at least 3 give a period). */
      unsigned int n_crossings = 0;
      /** Measured and linear-theory period [s], relative error of the measured one. */
      double period = 0., exact_period = 0., period_error = 0.;
      /** The last half-period's extreme |eta - d| over the first one's: the decay by
       *  viscosity and numerical damping over the record. */
      double amplitude_ratio = 0.;
    };

    /**
     * The period of the first sloshing mode of a tank of length @p length and still-water
     * depth @p depth from the record @p eta (time, surface elevation at a side wall), against
     * linear theory: omega^2 = g k tanh(k d), k = pi / L. The period is twice the mean time
     * between consecutive zero crossings of eta - d (linear interpolation between steps).
     */
    StandingWaveResult
    analyse_standing_wave(const std::vector<std::pair<double, double>> &eta,
                          double                                        depth,
                          double                                        length,
                          double                                        g);
  } // namespace fluid
} // namespace slidewave

#endif
