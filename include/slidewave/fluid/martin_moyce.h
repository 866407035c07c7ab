#ifndef slidewave_fluid_martin_moyce_h
#define slidewave_fluid_martin_moyce_h

#include <utility>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The surge front of the collapse of a water column of width a and height 2a
     * (n^2 = 2) on a dry horizontal bed, measured by Martin and Moyce (1952, Phil. Trans.
     * R. Soc. A 244, 312-324, their a = 2.25 in series), in their variables: the front's
     * distance from the back wall Z = x / a against T = t sqrt(2 g / a). The data set the
     * dam-break verifications of Lethe and OpenFOAM use.
     */
    struct MartinMoyceComparison
    {
      /** Experimental points inside the simulated time. */
      unsigned int n_points = 0;
      /** Largest and root-mean-square difference Z_simulated - Z_measured. */
      double max_error = 0., rms_error = 0.;
      /** The shift of the simulated T (in [0, 0.5]) that makes the RMS difference least,
       *  and that RMS: the experiment's gate took a finite time to lift, which codes
       *  commonly account for by such a shift (Lethe uses 0.175). */
      double best_shift = 0., rms_error_shifted = 0.;
    };

    /** The experiment's (T, Z) points. */
    const std::vector<std::pair<double, double>> &
    martin_moyce_front();

    /** Compares the front history @p front (time [s], distance of the front from the
     *  back wall [m]) of a column of width @p a [m] under gravity @p g [m/s^2]. */
    MartinMoyceComparison
    compare_with_martin_moyce(const std::vector<std::pair<double, double>> &front,
                              double                                        a,
                              double                                        g);
  } // namespace fluid
} // namespace slidewave

#endif
