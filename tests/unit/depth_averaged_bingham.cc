// The depth-integrated Bingham rheology of paper 001 (Eqs. 3-9, depth_averaged/bingham.h):
//  - zeta of Eq. 9 is a root of 48 zeta^2 - (114 + 32 a) zeta + 65 = 0 in [0, 1] for a from
//    0 to 1e6 (residual below 1e-12 of the terms: round-off), and within 0.05 of the root of
//    the cubic it replaces, zeta^3 - (3 + a) zeta + 2 = 0 (Eq. 8 with the sign of Eq. 7's
//    algebra; the quadratic's error is largest at a = 0, where it gives 0.951 for 1);
//  - its limits without a division by zero: tau_Y = 0, h = 0, |v| = 0, mu = 0, and all at
//    once;
//  - the stress: mu alone gives 2 mu D exactly; tau_Y alone, at a rate of 1e-12 1/s,
//    stays bounded by sqrt(2) tau_Y (the plain law) and is tau_Y m D at most with the
//    regularization; I_2 of Eq. 5 against a value worked by hand; a column of depth 0 or
//    1e-300 keeps the finite viscous part; no motion and no deformation give zero.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <slidewave/depth_averaged/bingham.h>

using namespace slidewave::depth_averaged;
using unit_check::check;

namespace
{
  /** The root in [0, 1] of zeta^3 - (3 + a) zeta + 2 by bisection. */
  double
  cubic_root(const double a)
  {
    double lo = 0., hi = 1.;
    for (int k = 0; k < 200; ++k)
      {
        const double mid                                       = 0.5 * (lo + hi);
        (mid * mid * mid - (3. + a) * mid + 2. > 0. ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }
} // namespace

int
main()
{
  std::printf("zeta (Eq. 9)\n");
  {
    double largest_residual = 0., largest_difference = 0., smallest = 1., largest = 0.;
    for (const double a : {0., 1e-6, 0.01, 0.1, 0.5, 1., 3., 10., 100., 1e4, 1e6})
      {
        // a = 6 mu |v| / (tau_Y h) with tau_Y = h = 1: mu |v| = a / 6.
        const double zeta     = bingham::plug_ratio(a / 6., 1., 1., 1.);
        const double b        = 114. + 32. * a;
        const double residual = std::abs(48. * zeta * zeta - b * zeta + 65.) / (b + 65.);
        largest_residual      = std::max(largest_residual, residual);
        largest_difference    = std::max(largest_difference, std::abs(zeta - cubic_root(a)));
        smallest              = std::min(smallest, zeta);
        largest               = std::max(largest, zeta);
      }
    std::printf("  zeta from %.4f to %.4e; largest relative residual %.1e; largest difference "
                "from the cubic's root %.4f\n",
                largest,
                smallest,
                largest_residual,
                largest_difference);
    check(largest_residual < 1e-12, "a root of Eq. 9");
    check(smallest > 0. && largest <= 1., "in (0, 1]");
    check(largest_difference < 0.05, "within 0.05 of the cubic's root (Eq. 8)");
    const double at_rest = bingham::plug_ratio(2000., 30., 0., 1.);
    std::printf("  |v| = 0: %.6f\n", at_rest);
    check(std::abs(at_rest - 130. / (114. + std::sqrt(516.))) < 1e-15,
          "|v| = 0: 130 / (114 + sqrt(516))");
    check(bingham::plug_ratio(0., 30., 2., 1.) == at_rest, "mu = 0: the same");
    check(bingham::plug_ratio(2000., 0., 2., 1.) == 0., "tau_Y = 0: 0");
    check(bingham::plug_ratio(2000., 30., 2., 0.) == 0., "h = 0: 0");
    check(bingham::plug_ratio(0., 0., 0., 0.) == 0., "everything zero: 0, no NaN");
  }

  std::printf("stress (Eqs. 3-6)\n");
  {
    const double dxx = 0.3, dyy = -0.1, dxy = 0.2;
    const auto   viscous = bingham::stress(dxx, dyy, dxy, 1., 0.5, 2., 10., 0., 0.);
    check(viscous.xx == 20. * dxx && viscous.yy == 20. * dyy && viscous.xy == 20. * dxy,
          "mu alone: 2 mu D exactly");

    // At rest (v = 0) the vertical shear vanishes and I_2 = 1/2 (dxx^2 + dyy^2 + (dxx +
    // dyy)^2) + dxy^2 = 1/2 (0.09 + 0.01 + 0.04) + 0.04 = 0.11.
    const auto plain = bingham::stress(dxx, dyy, dxy, 0., 0., 1., 0., 30., 0.);
    check(std::abs(plain.xx - 30. / std::sqrt(0.11) * dxx) < 1e-13, "I_2 at rest: 0.11");
    // With motion, d_z v = 3 / (2 + zeta) v / h adds (d_z u / 2)^2 + (d_z v / 2)^2.
    {
      const double zeta  = bingham::plug_ratio(10., 30., std::sqrt(1.25), 2.);
      const double shear = 1.5 / ((2. + zeta) * 2.);
      const double I2    = 0.11 + shear * shear * 1.25;
      const auto   both  = bingham::stress(dxx, dyy, dxy, 1., 0.5, 2., 10., 30., 0.);
      check(std::abs(both.xy - (20. + 30. / std::sqrt(I2)) * dxy) < 1e-13,
            "I_2 with the vertical shear of Eq. 6");
    }

    const double tiny  = 1e-12;
    const auto   yield = bingham::stress(tiny, -tiny, tiny, 0., 0., 1., 0., 30., 0.);
    const double size
      = std::sqrt(yield.xx * yield.xx + yield.yy * yield.yy + 2. * yield.xy * yield.xy);
    const auto smooth = bingham::stress(tiny, -tiny, tiny, 0., 0., 1., 0., 30., 100.);
    std::printf("  |sigma| at a rate of 1e-12: plain %.4f Pa, regularized (m = 100 s) %.3e Pa\n",
                size,
                std::abs(smooth.xx));
    check(size <= std::sqrt(2.) * 30. * (1. + 1e-12) && size > 1.,
          "plain: bounded by sqrt(2) tau_Y");
    check(std::abs(smooth.xx - 30. * 100. * tiny) < 1e-8 * 30. * 100. * tiny,
          "regularized: tau_Y m D at rest");
    const auto fast_plain  = bingham::stress(dxx, dyy, dxy, 0., 0., 1., 0., 30., 0.);
    const auto fast_smooth = bingham::stress(dxx, dyy, dxy, 0., 0., 1., 0., 30., 1e4);
    check(std::abs(fast_smooth.xx - fast_plain.xx) < 1e-12 * std::abs(fast_plain.xx),
          "regularized = plain once m sqrt(I_2) >> 1");

    for (const double h : {0., 1e-300})
      {
        const auto dry = bingham::stress(dxx, dyy, dxy, 1., 0.5, h, 10., 30., 100.);
        check(std::isfinite(dry.xx) && std::isfinite(dry.xy)
                && std::abs(dry.xx - 20. * dxx) < 1e-9 * 20. * dxx,
              h == 0. ? "h = 0: the viscous part" : "h = 1e-300: the viscous part");
      }
    const auto still = bingham::stress(0., 0., 0., 0., 0., 1., 2000., 30., 0.);
    check(still.xx == 0. && still.yy == 0. && still.xy == 0., "no motion: zero stress");
  }
  return unit_check::finish();
}
