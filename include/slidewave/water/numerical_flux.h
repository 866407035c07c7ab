#ifndef slidewave_water_numerical_flux_h
#define slidewave_water_numerical_flux_h

#include <algorithm>
#include <cmath>

namespace slidewave
{
  namespace water
  {
    /**
     * Numerical fluxes of the 1D shallow water equations for the conserved variables
     * U = (h, hu) (paper 000, Eq. 24). Inline: they run once per interface per stage.
     *
     * States with h <= dry_depth are dry: their velocity is taken as zero.
     */
    namespace numerical_flux
    {
      /**
       * HLL flux with Einfeldt's wave-speed estimates (the extremes of the Roe and the one-
       * sided speeds); at a wet/dry interface the dry-front speed u +- 2 sqrt(g h) of the
       * wet side. Positivity preserving at Courant numbers up to 1.
       */
      inline void
      hll(const double h_l,
          const double q_l,
          const double h_r,
          const double q_r,
          const double g,
          const double dry_depth,
          double      &flux_h,
          double      &flux_q)
      {
        const bool wet_l = h_l > dry_depth;
        const bool wet_r = h_r > dry_depth;
        if (!wet_l && !wet_r)
          {
            flux_h = 0.;
            flux_q = 0.;
            return;
          }
        const double u_l = wet_l ? q_l / h_l : 0.;
        const double u_r = wet_r ? q_r / h_r : 0.;
        const double c_l = std::sqrt(g * h_l);
        const double c_r = std::sqrt(g * h_r);

        double s_l, s_r;
        if (!wet_l)
          {
            s_l = u_r - 2. * c_r;
            s_r = u_r + c_r;
          }
        else if (!wet_r)
          {
            s_l = u_l - c_l;
            s_r = u_l + 2. * c_l;
          }
        else
          {
            const double sqrt_h_l = std::sqrt(h_l);
            const double sqrt_h_r = std::sqrt(h_r);
            const double u_hat    = (sqrt_h_l * u_l + sqrt_h_r * u_r) / (sqrt_h_l + sqrt_h_r);
            const double c_hat    = std::sqrt(0.5 * g * (h_l + h_r));
            s_l                   = std::min(u_l - c_l, u_hat - c_hat);
            s_r                   = std::max(u_r + c_r, u_hat + c_hat);
          }

        const double f_h_l = wet_l ? q_l : 0.;
        const double f_q_l = (wet_l ? q_l * u_l : 0.) + 0.5 * g * h_l * h_l;
        const double f_h_r = wet_r ? q_r : 0.;
        const double f_q_r = (wet_r ? q_r * u_r : 0.) + 0.5 * g * h_r * h_r;

        if (s_l >= 0.)
          {
            flux_h = f_h_l;
            flux_q = f_q_l;
          }
        else if (s_r <= 0.)
          {
            flux_h = f_h_r;
            flux_q = f_q_r;
          }
        else
          {
            const double inv = 1. / (s_r - s_l);
            flux_h           = (s_r * f_h_l - s_l * f_h_r + s_l * s_r * (h_r - h_l)) * inv;
            flux_q           = (s_r * f_q_l - s_l * f_q_r + s_l * s_r * (q_r - q_l)) * inv;
          }
      }



      /**
       * Harten–Hyman entropy fix: the absolute value of a Roe eigenvalue @p lambda, smoothed
       * where the characteristic speeds @p lambda_l, @p lambda_r on the two sides straddle
       * zero (transonic rarefaction), so that no expansion shock forms.
       */
      inline double
      entropy_fixed_abs(const double lambda, const double lambda_l, const double lambda_r)
      {
        const double delta = std::max(0., std::max(lambda - lambda_l, lambda_r - lambda));
        const double a     = std::abs(lambda);
        return a < delta ? 0.5 * (lambda * lambda + delta * delta) / delta : a;
      }



      /**
       * Roe's flux (paper 000, Eqs. 30–32): the average of the physical fluxes minus the
       * upwinding |A|(U_r - U_l) with the Roe matrix at the averaged state ĥ = (h_l + h_r)/2,
       * û = (sqrt(h_l) u_l + sqrt(h_r) u_r)/(sqrt(h_l) + sqrt(h_r)), and the Harten–Hyman
       * entropy fix. Roe's linearization does not preserve positivity next to a dry state, so
       * interfaces with a dry side use the HLL flux.
       */
      inline void
      roe(const double h_l,
          const double q_l,
          const double h_r,
          const double q_r,
          const double g,
          const double dry_depth,
          double      &flux_h,
          double      &flux_q)
      {
        if (h_l <= dry_depth || h_r <= dry_depth)
          {
            hll(h_l, q_l, h_r, q_r, g, dry_depth, flux_h, flux_q);
            return;
          }
        const double sqrt_h_l = std::sqrt(h_l);
        const double sqrt_h_r = std::sqrt(h_r);
        const double sqrt_g   = std::sqrt(g);
        const double u_l      = q_l / h_l;
        const double u_r      = q_r / h_r;
        const double u_hat    = (sqrt_h_l * u_l + sqrt_h_r * u_r) / (sqrt_h_l + sqrt_h_r);
        const double c_hat    = std::sqrt(0.5 * g * (h_l + h_r));
        const double lambda_1 = u_hat - c_hat;
        const double lambda_2 = u_hat + c_hat;

        const double c_l   = sqrt_g * sqrt_h_l;
        const double c_r   = sqrt_g * sqrt_h_r;
        const double abs_1 = entropy_fixed_abs(lambda_1, u_l - c_l, u_r - c_r);
        const double abs_2 = entropy_fixed_abs(lambda_2, u_l + c_l, u_r + c_r);

        // Wave strengths: R^{-1} (U_r - U_l) with R = [[1, 1], [lambda_1, lambda_2]].
        const double dh      = h_r - h_l;
        const double dq      = q_r - q_l;
        const double inv_2c  = 0.5 / c_hat;
        const double alpha_1 = (lambda_2 * dh - dq) * inv_2c;
        const double alpha_2 = (dq - lambda_1 * dh) * inv_2c;

        const double w_1 = abs_1 * alpha_1;
        const double w_2 = abs_2 * alpha_2;
        flux_h           = 0.5 * (q_l + q_r - w_1 - w_2);
        flux_q           = 0.5
                 * (q_l * u_l + q_r * u_r + 0.5 * g * (h_l * h_l + h_r * h_r) - w_1 * lambda_1
                    - w_2 * lambda_2);
      }
    } // namespace numerical_flux



    /**
     * Slope limiters for the MUSCL reconstruction, applied to the one-sided slopes @p a
     * (towards the left neighbour) and @p b (towards the right one) on non-uniform cells.
     * All return zero at extrema (a b <= 0).
     */
    namespace slope_limiter
    {
      inline double
      minmod(const double a, const double b)
      {
        if (a * b <= 0.)
          return 0.;
        return std::abs(a) < std::abs(b) ? a : b;
      }

      inline double
      van_leer(const double a, const double b)
      {
        const double ab = a * b;
        return ab > 0. ? 2. * ab / (a + b) : 0.;
      }

      inline double
      superbee(const double a, const double b)
      {
        if (a * b <= 0.)
          return 0.;
        const double abs_a = std::abs(a), abs_b = std::abs(b);
        const double m = std::max(std::min(2. * abs_a, abs_b), std::min(abs_a, 2. * abs_b));
        return a > 0. ? m : -m;
      }
    } // namespace slope_limiter
  }   // namespace water
} // namespace slidewave

#endif
