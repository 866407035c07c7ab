// The critical-state dilatancy of the small-strain Drucker-Prager material ('Dilatancy law =
// critical state': tan psi = K (n_c - n); materials::Material::dilatancy_coefficient) for
// the skeleton of granular water:
//  1. alpha_psi = tan psi / sqrt(9 + 12 tan^2 psi): zero at n = n_c, positive (dilation)
//     below it, negative (compaction) above it, held within [-alpha_phi, alpha_phi] and,
//     for a nearly incompressible skeleton (nu = 0.45), where the return stays well posed
//     (G + 9 K alpha_phi alpha_psi = 0.1 G);
//  2. the update with a point's alpha_psi is the update of the material made with the
//     matching fixed angle, to round-off, for a stress beyond the cone;
//  3. a drained simple shear (shear strain increments of 1e-4; the volumetric strain of
//     each step found so that the mean stress stays at p0 = 10 kPa) of a dense (n = 0.38)
//     and a loose (n = 0.46) packing, n_c = 0.42, K = 4.09, phi = 30 deg. With the
//     stress at rest on the cone, the plane-strain matched flow rule dilates by
//     d eps_v / d gamma = sin psi exactly (3 alpha_psi / sqrt(1 - 3 alpha_psi^2), with
//     the plane-strain constraint on the plastic flow), and the solid volume is fixed,
//     so the porosity follows dn/d gamma = (1 - n) sin psi(n), integrated here by RK4 with
//     1e-5 steps: both packings approach n_c from their sides, as that ODE says, within
//     2e-4 at gamma = 0.05, 0.2 and 1 (the element's elastic start and its first-order
//     steps in gamma); with a fixed psi = 10 deg the measured rate is sin 10 deg to 1e-6;
//  4. the finite-strain model (hencky drucker prager) takes the law too: its material has
//     the same alpha_psi(n) as the small-strain one, bounds included, and its return with a
//     point's (negative) alpha_psi is the return of the model made with the matching fixed
//     angle, to round-off, for a stretch beyond the cone.
// Exits non-zero on failure.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/symmetric_tensor.h>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/hencky_drucker_prager.h>
#include <slidewave/materials/material.h>

using namespace slidewave::materials;
using unit_check::check;

namespace
{
  MaterialParameters
  sand(const bool critical_state, const double dilatancy_angle = 0.)
  {
    MaterialParameters m;
    m.name                     = "sand";
    m.model                    = MaterialModel::drucker_prager;
    m.youngs_modulus           = 1e7;
    m.poisson_ratio            = 0.3;
    m.friction_angle           = 30.;
    m.cohesion                 = 0.;
    m.dilatancy_angle          = dilatancy_angle;
    m.critical_state_dilatancy = critical_state;
    m.critical_porosity        = 0.42;
    m.dilatancy_factor         = 4.09;
    return m;
  }

  double
  mean(const dealii::SymmetricTensor<2, 3> &s)
  {
    return dealii::trace(s) / 3.;
  }

  /** The drained simple shear: porosity and the last step's d eps_v / d gamma. */
  struct Shear
  {
    double porosity, rate;
  };

  /** Shears from an isotropic -p0 to @p gamma, the mean stress held at -p0. */
  Shear
  simple_shear(const Material &material, double n, const double gamma, const bool state)
  {
    const double                  p0 = 1e4, step = 1e-4;
    dealii::SymmetricTensor<2, 3> stress  = -p0 * dealii::unit_symmetric_tensor<3>();
    double                        plastic = 0., rate = 0.;
    const unsigned int            steps = static_cast<unsigned int>(std::lround(gamma / step));
    for (unsigned int k = 0; k < steps; ++k)
      {
        const double alpha = state ? material.dilatancy_coefficient(n) : 0.;
        // The mean stress after the step is piecewise linear in the volumetric increment:
        // secant iterations find the one that keeps it at -p0.
        const auto after = [&](const double volumetric, dealii::SymmetricTensor<2, 3> &s) {
          dealii::SymmetricTensor<2, 3> increment;
          increment[0][0] = increment[1][1] = 0.5 * volumetric;
          increment[0][1]                   = 0.5 * step;
          s                                 = stress;
          double eps                        = plastic;
          if (state)
            material.update_stress(s, increment, 0., eps, alpha);
          else
            material.update_stress(s, increment, 0., eps);
          return mean(s) + p0;
        };
        dealii::SymmetricTensor<2, 3> s;
        double                        a = 0., fa = after(a, s), b = 1e-4, fb = after(b, s);
        for (unsigned int i = 0; i < 50 && std::abs(fb) > 1e-9 * p0 && fb != fa; ++i)
          {
            const double c = b - fb * (b - a) / (fb - fa);
            a              = b;
            fa             = fb;
            b              = c;
            fb             = after(b, s);
          }
        dealii::SymmetricTensor<2, 3> increment;
        increment[0][0] = increment[1][1] = 0.5 * b;
        increment[0][1]                   = 0.5 * step;
        if (state)
          material.update_stress(stress, increment, 0., plastic, alpha);
        else
          material.update_stress(stress, increment, 0., plastic);
        rate = b / step;
        n    = 1. - (1. - n) / (1. + b);
      }
    return {n, rate};
  }

  /** dn/d gamma = (1 - n) sin psi(n) by RK4 from @p n to @p gamma. */
  double
  porosity_ode(const MaterialParameters &m, double n, const double gamma)
  {
    const auto f = [&m](const double x) {
      const double t = m.dilatancy_factor * (m.critical_porosity - x);
      return (1. - x) * t / std::sqrt(1. + t * t);
    };
    const double       h     = 1e-5;
    const unsigned int steps = static_cast<unsigned int>(std::lround(gamma / h));
    for (unsigned int k = 0; k < steps; ++k)
      {
        const double k1 = f(n), k2 = f(n + 0.5 * h * k1), k3 = f(n + 0.5 * h * k2),
                     k4 = f(n + h * k3);
        n += h * (k1 + 2. * k2 + 2. * k3 + k4) / 6.;
      }
    return n;
  }
} // namespace

int
main()
{
  const MaterialParameters parameters = sand(true);
  const Material           material(parameters);
  const double alpha_phi = DruckerPrager::plane_strain_coefficient(parameters.friction_angle);

  // 1.
  std::printf("alpha_psi (alpha_phi = %.6f):\n", alpha_phi);
  const double at_critical = material.dilatancy_coefficient(0.42);
  const double dense       = material.dilatancy_coefficient(0.38),
               loose       = material.dilatancy_coefficient(0.46);
  const double t           = 4.09 * 0.04;
  std::printf("  n = 0.42: %.3e  n = 0.38: %.9f (tan psi = 0.1636: %.9f)  n = 0.46: %.9f\n",
              at_critical,
              dense,
              t / std::sqrt(9. + 12. * t * t),
              loose);
  check(at_critical == 0. && std::abs(dense - t / std::sqrt(9. + 12. * t * t)) < 1e-15
          && std::abs(loose + dense) < 1e-15,
        "zero at n_c, tan psi = K (n_c - n) on both sides");
  const double very_dense = material.dilatancy_coefficient(0.),
               very_loose = material.dilatancy_coefficient(0.99);
  std::printf("  n = 0: %.9f  n = 0.99: %.9f\n", very_dense, very_loose);
  check(std::abs(very_dense - alpha_phi) < 1e-15 && std::abs(very_loose + alpha_phi) < 1e-15,
        "held within [-alpha_phi, alpha_phi]");
  {
    // Nearly incompressible (nu = 0.45): G + 9 K alpha_phi alpha_psi reaches 0.1 G first.
    MaterialParameters stiff = parameters;
    stiff.poisson_ratio      = 0.45;
    const Material stiff_material(stiff);
    const double   G = 1e7 / 2.9, K = 1e7 / (3. * 0.1);
    const double   lowest = stiff_material.dilatancy_coefficient(0.99);
    std::printf("  nu = 0.45, n = 0.99: %.9f (G + 9 K alpha_phi alpha_psi = %.12f G)\n",
                lowest,
                (G + 9. * K * alpha_phi * lowest) / G);
    check(lowest > -alpha_phi && std::abs((G + 9. * K * alpha_phi * lowest) / G - 0.1) < 1e-12,
          "held where the return is well posed");
  }

  // 2.
  {
    const double                  psi = std::atan(t) * 180. / M_PI;
    const Material                fixed(sand(false, psi));
    dealii::SymmetricTensor<2, 3> a, b, increment;
    a[0][0] = b[0][0] = -1e4;
    a[1][1] = b[1][1] = -2e4;
    a[2][2] = b[2][2] = -1.5e4;
    increment[0][1]   = 2e-3;
    increment[0][0]   = -1e-4;
    double ea = 0., eb = 0.;
    material.update_stress(a, increment, 0.01, ea, dense);
    fixed.update_stress(b, increment, 0.01, eb);
    const double difference = (a - b).norm() / b.norm();
    std::printf("update with alpha_psi(0.38) against the material of psi = %.6f deg: "
                "relative difference %.1e, plastic strain %.6e and %.6e\n",
                psi,
                difference,
                ea,
                eb);
    check(difference < 1e-14 && std::abs(ea - eb) < 1e-15 && ea > 0.,
          "the same return as the fixed angle");
  }

  // 3.
  std::printf("drained simple shear at p0 = 10 kPa:\n");
  bool follows = true;
  for (const double n0 : {0.38, 0.46})
    for (const double gamma : {0.05, 0.2, 1.})
      {
        const Shear  shear = simple_shear(material, n0, gamma, true);
        const double exact = porosity_ode(parameters, n0, gamma);
        std::printf("  n0 = %.2f, gamma = %.2f: n = %.6f, ODE %.6f (difference %.1e), "
                    "d eps_v / d gamma = %+.6f\n",
                    n0,
                    gamma,
                    shear.porosity,
                    exact,
                    shear.porosity - exact,
                    shear.rate);
        follows = follows && std::abs(shear.porosity - exact) < 2e-4;
      }
  check(follows, "the porosity follows dn / d gamma = (1 - n) sin psi(n) towards n_c");
  {
    const Material fixed(sand(false, 10.));
    const Shear    shear = simple_shear(fixed, 0.4, 0.05, false);
    std::printf("  fixed psi = 10 deg: d eps_v / d gamma = %.9f, sin 10 deg = %.9f\n",
                shear.rate,
                std::sin(10. * M_PI / 180.));
    check(std::abs(shear.rate - std::sin(10. * M_PI / 180.)) < 1e-6,
          "a fixed angle dilates at sin psi (the plane-strain match)");
  }

  // 4.
  {
    MaterialParameters hencky = parameters;
    hencky.model              = MaterialModel::hencky_drucker_prager;
    hencky.tension_cutoff     = 0.;
    const Material hencky_material(hencky);
    bool           same = true;
    for (const double n : {0., 0.38, 0.42, 0.46, 0.99})
      same = same && hencky_material.dilatancy_coefficient(n) == material.dilatancy_coefficient(n);
    check(same, "the Hencky material's alpha_psi(n) is the small-strain one's, bounds included");

    const double              psi = -std::atan(t) * 180. / M_PI; // the loose packing's
    const HenckyDruckerPrager with_angle(
      hencky.youngs_modulus, hencky.poisson_ratio, hencky.friction_angle, hencky.cohesion, psi);
    const HenckyDruckerPrager without_angle(
      hencky.youngs_modulus, hencky.poisson_ratio, hencky.friction_angle, hencky.cohesion, 0.);
    // A stretch beyond the cone: shortening along y, shear in x-y.
    dealii::Tensor<2, 3> f;
    f[0][0]                            = 1.;
    f[1][1]                            = 0.99;
    f[2][2]                            = 1.;
    f[0][1]                            = 0.02;
    dealii::SymmetricTensor<2, 3> be_a = dealii::unit_symmetric_tensor<3>(), be_b = be_a;
    double                        ea = 0., eb = 0.;
    const HenckyStep a      = without_angle.update(be_a, f, dealii::determinant(f), ea, loose);
    const HenckyStep b      = with_angle.update(be_b, f, dealii::determinant(f), eb);
    const double difference = (a.cauchy_stress - b.cauchy_stress).norm() / b.cauchy_stress.norm();
    const double volumetric = dealii::trace(a.plastic_strain_increment);
    std::printf("Hencky: update with alpha_psi(0.46) against the model of psi = %.6f deg: "
                "relative difference %.1e, b^e %.1e, plastic strain %.6e and %.6e, plastic "
                "volumetric log strain %.6e (3 alpha_psi dgamma < 0: compaction)\n",
                psi,
                difference,
                (be_a - be_b).norm(),
                ea,
                eb,
                volumetric);
    check(difference < 1e-14 && (be_a - be_b).norm() < 1e-14 && std::abs(ea - eb) < 1e-15 && ea > 0.
            && a.region == HenckyReturn::cone && volumetric < 0.,
          "the Hencky return with a point's alpha_psi is the fixed angle's, and compacts");
  }
  return unit_check::finish();
}
