#ifndef slidewave_fluid_phase_profile_h
#define slidewave_fluid_phase_profile_h

#include <algorithm>
#include <cmath>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The phase field's equilibrium profile across a flat interface, phi = 1 / (1 +
     * exp(-d / epsilon)), at the signed distance @p d from the surface (positive in the
     * water) for the interface thickness @p epsilon; the exponent is clamped so that the
     * profile is exactly 0 or 1 far from the surface without overflow.
     */
    inline double
    equilibrium_phase(const double d, const double epsilon)
    {
      return 1. / (1. + std::exp(std::clamp(-d / epsilon, -700., 700.)));
    }
  } // namespace fluid
} // namespace slidewave

#endif
