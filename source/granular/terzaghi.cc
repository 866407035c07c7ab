#include <cmath>
#include <slidewave/granular/terzaghi.h>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** The terms of Terzaghi's series up to where exp(-M^2 T_v) < 1e-16 (at most
       *  100000 of them: T_v -> 0 needs many). */
      template <class Term>
      double
      series(const double time_factor, const Term &term)
      {
        double sum = 0.;
        for (unsigned int m = 0; m < 100000; ++m)
          {
            const double M     = (2. * m + 1.) * M_PI / 2.;
            const double decay = std::exp(-M * M * time_factor);
            if (decay < 1e-16)
              break;
            sum += term(M) * decay;
          }
        return sum;
      }
    } // namespace



    double
    terzaghi_pore_pressure(const double depth_ratio, const double time_factor)
    {
      return series(time_factor,
                    [&](const double M) { return 2. / M * std::sin(M * depth_ratio); });
    }



    double
    terzaghi_average_degree(const double time_factor)
    {
      return 1. - series(time_factor, [](const double M) { return 2. / (M * M); });
    }



    double
    consolidation_coefficient(const double youngs_modulus,
                              const double poisson_ratio,
                              const double permeability,
                              const double viscosity)
    {
      const double nu                  = poisson_ratio;
      const double constrained_modulus = youngs_modulus * (1. - nu) / ((1. + nu) * (1. - 2. * nu));
      return permeability * constrained_modulus / viscosity;
    }
  } // namespace granular
} // namespace slidewave
