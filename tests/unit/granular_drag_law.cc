// The drag law between the granular skeleton and the pore water (paper 002,
// Eqs. 3 and 4; granular::DragLaw): the Kozeny-Carman permeability
// k = D50^2 n^3 / (180 (1 - n)^2) and the Forchheimer-like drag coefficient
// C = n^2 mu / k + n^3 rho F / sqrt(k) |w|, F = 1.75 / sqrt(150 n^3), against
// numbers computed by hand (water, rho = 1000 kg/m^3, mu = 1e-3 Pa s, in sand
// of D50 = 1 mm at n = 0.4); the limits (n -> 1 at the cap 0.99, Darcy's law
// at low Reynolds number, the Forchheimer term growing with |w|); the refusal
// of unphysical input. Exits non-zero when a check fails.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/tensor.h>
#include <slidewave/granular/drag_law.h>

using slidewave::granular::DragLaw;

namespace
{
  /** Prints PASS or FAIL with the value, the tolerance and why it is that. */
  void
  verdict(const char *what, const double error, const double tolerance, const char *why)
  {
    const bool pass = std::abs(error) <= tolerance;
    std::printf(
      "%s: %s = %.3e (tolerance %.0e: %s)\n", pass ? "PASS" : "FAIL", what, error, tolerance, why);
    unit_check::all_passed = unit_check::all_passed && pass;
  }

  double
  relative_error(const double value, const double expected)
  {
    return (value - expected) / expected;
  }

  const char *const rounding = "a few roundings of double precision";

  /** Whether @p f throws an InputError; prints its whole message (parameter, value, allowed). */
  template <typename Function>
  int
  refused(const Function &f)
  {
    try
      {
        f();
      }
    catch (const slidewave::InputError &e)
      {
        std::printf("  refused: %s\n", e.what());
        return 1;
      }
    std::printf("  NOT refused\n");
    return 0;
  }
} // namespace



int
main()
{
  const double  rho = 1000.;
  const double  mu  = 1e-3;
  const double  d50 = 1e-3;
  const DragLaw law(rho, mu, d50);

  std::printf("* Values at n = 0.4, D50 = 1 mm (hand-computed with the formulas of the header)\n");
  // k = 1e-6 * 0.064 / (180 * 0.36) = 9.87654321e-10 m^2
  const double k = law.permeability(0.4);
  std::printf("k = %.9e m^2 (hydraulic conductivity k rho g / mu = %.4e m/s)\n",
              k,
              k * rho * 9.81 / mu);
  verdict("relative error of k against 0.064e-6 / 64.8",
          relative_error(k, 0.064e-6 / 64.8),
          1e-14,
          rounding);
  // F = 1.75 / sqrt(9.6) = 0.564810071
  const double F = DragLaw::forchheimer_factor(0.4);
  std::printf("F = %.9f\n", F);
  verdict("relative error of F against 1.75 / sqrt(9.6)",
          relative_error(F, 1.75 / std::sqrt(9.6)),
          1e-14,
          rounding);
  // n^2 mu / k = 0.16e-3 / 9.87654321e-10 = 162000 kg/(m^3 s)
  const double darcy = law.darcy_coefficient(0.4, k);
  std::printf("Darcy coefficient n^2 mu / k = %.6f kg/(m^3 s)\n", darcy);
  verdict("relative error of the Darcy coefficient against 162000",
          relative_error(darcy, 162000.),
          1e-14,
          rounding);
  // n^3 rho F / sqrt(k) = 0.064 * 1000 * 0.564810071 / 3.14269681e-5 = 1150217.37 per m/s
  const double c_slow = law.drag_coefficient(0.4, k, 0.01);
  std::printf("C(|w| = 0.01 m/s) = %.6f kg/(m^3 s)\n", c_slow);
  verdict("relative error of C(0.01 m/s) against 162000 + 11502.1737076",
          relative_error(c_slow, 162000. + 11502.1737076085),
          1e-12,
          "the hand value has 12 digits");

  const dealii::Tensor<1, 2> w({0.006, -0.008});
  const dealii::Tensor<1, 2> drag = law.drag_force(0.4, k, w);
  std::printf("drag for w = (0.006, -0.008) m/s: (%.6f, %.6f) N/m^3\n", drag[0], drag[1]);
  verdict("relative error of the drag force against C(0.01) w (|w| = 0.01)",
          (drag - c_slow * w).norm() / (c_slow * w.norm()),
          1e-14,
          rounding);
  const dealii::Tensor<1, 3> w3({0., 0.006, -0.008});
  verdict("3D drag force equals the 2D one (component-wise)",
          (law.drag_force(0.4, k, w3)[1] - drag[0]) / drag[0],
          1e-15,
          "same arithmetic");

  std::printf("\n* n -> 1: the porosity cap 0.99 (paper 002, section 3.2)\n");
  const double k_cap = DragLaw::porosity_cap * DragLaw::porosity_cap * DragLaw::porosity_cap * d50
                       * d50 / (180. * 1e-4);
  for (const double n : {0.4, 0.6, 0.8, 0.9, 0.99, 0.999, 1.})
    std::printf("n = %.3f: k = %.6e m^2  k / D50^2 = %.6e\n",
                n,
                law.permeability(n),
                law.permeability(n) / (d50 * d50));
  verdict("relative error of k(1) against k(0.99) = 0.99^3 D50^2 / (180 1e-4)",
          relative_error(law.permeability(1.), k_cap),
          1e-14,
          rounding);
  std::printf("k(0.99) / k(0.4) = %.1f\n", law.permeability(0.99) / k);
  verdict("k(0.99) / k(0.4) > 1e4 (water nearly free of grains)",
          law.permeability(0.99) / k > 1e4 ? 0. : 1.,
          0.,
          "a yes/no check");
  bool increasing = true;
  for (double n = 0.01; n < 0.99; n += 0.01)
    increasing = increasing && law.permeability(n + 0.01) > law.permeability(n);
  verdict("k(n) increasing on 0.01 <= n <= 0.99 (1 when not)",
          increasing ? 0. : 1.,
          0.,
          "a yes/no check");

  std::printf("\n* Low Reynolds number: Darcy's law\n");
  for (const double speed : {1e-6, 1e-4, 1e-2, 1.})
    {
      const double ratio = law.drag_coefficient(0.4, k, speed) / darcy - 1.;
      // Forchheimer / Darcy = 1.75 n Re_p / (sqrt(150 * 180) (1 - n))
      const double re       = law.particle_reynolds_number(speed);
      const double expected = 1.75 * 0.4 * re / (std::sqrt(150. * 180.) * 0.6);
      std::printf("|w| = %.0e m/s: Re_p = %.3e  C / (n^2 mu / k) - 1 = %.6e (1.75 n Re_p / "
                  "(sqrt(27000) (1 - n)) = %.6e)\n",
                  speed,
                  re,
                  ratio,
                  expected);
      verdict("  relative error of the Forchheimer/Darcy ratio against the hand formula",
              relative_error(ratio, expected),
              1e-9,
              "C / Darcy - 1 cancels digits: 1e-16 / ratio, ratio >= 7e-6");
    }
  // Steady seepage n grad p = -C w: the Darcy flux n w = -(k / mu) grad p.
  const double gradient = -9810.; // a unit hydraulic gradient, Pa/m
  const double speed    = -0.4 * gradient / law.drag_coefficient(0.4, k, 0.);
  std::printf("seepage under a unit hydraulic gradient: n w = %.6e m/s, k rho g / mu = %.6e "
              "m/s\n",
              0.4 * speed,
              k * 9810. / mu);
  verdict("relative error of the Darcy flux n w against -(k / mu) grad p at |w| -> 0",
          relative_error(0.4 * speed, -k / mu * gradient),
          1e-14,
          rounding);

  std::printf("\n* The Forchheimer term grows with |w|\n");
  double previous = 0.;
  bool   growing  = true;
  for (const double s : {0., 0.01, 0.1, 1., 10.})
    {
      const double c = law.drag_coefficient(0.4, k, s);
      std::printf("|w| = %5.2f m/s: C = %.6e  Forchheimer part = %.6e\n", s, c, c - darcy);
      growing  = growing && (s == 0. || c > previous);
      previous = c;
    }
  verdict("C strictly increasing in |w| (1 when not)", growing ? 0. : 1., 0., "a yes/no check");
  const double slope = (law.drag_coefficient(0.4, k, 2.) - law.drag_coefficient(0.4, k, 1.));
  verdict("relative error of dC/d|w| against n^3 rho F / sqrt(k) = 1150217.3707608",
          relative_error(slope, 1150217.3707608487),
          1e-11,
          "a difference of two numbers of 1e6, rounded at 1e-10");

  std::printf("\n* Refused input\n");
  int refusals = 0;
  refusals += refused([&]() { law.permeability(0.); });
  refusals += refused([&]() { law.permeability(-0.1); });
  refusals += refused([&]() { law.permeability(1.2); });
  refusals += refused([&]() { law.permeability(std::nan("")); });
  refusals += refused([&]() { DragLaw(rho, mu, 0.); });
  refusals += refused([&]() { DragLaw(rho, mu, -1e-3); });
  refusals += refused([&]() { DragLaw(0., mu, d50); });
  refusals += refused([&]() { DragLaw(rho, -mu, d50); });
  refusals += refused([&]() { law.drag_coefficient(0.4, 0., 0.1); });
  refusals += refused([&]() { law.drag_coefficient(0.4, k, -0.1); });
  verdict("refusals missing out of 10 (n = 0, -0.1, 1.2, NaN; D50 = 0, -1 mm; rho = 0; mu < "
          "0; k = 0; |w| < 0)",
          10 - refusals,
          0.,
          "a count");

  return unit_check::finish();
}
