// The rate-dependent friction of the small-strain Drucker-Prager material ('Friction law';
// materials::Material::friction_tangent and update_stress_at_rate):
//  1. the law tan phi = mu_s + (mu_2 - mu_s) X / (X + X_0) against its closed form, for the
//     inertial number I = gamma_dot d sqrt(rho_s / p') and the viscous number J = eta_f
//     gamma_dot / p': mu_s at rest and without pressure (p' <= 0), mu_2 for a pressure so
//     small that X overflows, the mean of mu_s and mu_2 at X = X_0, and values at X = 0.01,
//     0.3, 10 X_0 to 1e-14;
//  2. a drained simple shear at a constant rate gamma_dot (shear strain increments of
//     gamma_dot dt, dt = 1e-4 s, from an isotropic 10 kPa; psi = 0, so the mean stress
//     stays at p0): once the stress is on the cone, sqrt(J2) = 3 alpha_phi p0 + k_c with
//     alpha_phi of the rate's tan phi and k_c the static one, for inertial numbers 1e-4 ... 10
//     and viscous numbers alike, without and with a cohesion of 2 kPa, to 1e-12 of p0; the
//     stress ratio rises with the rate; with psi = -5 deg (the material's own, the NaN
//     argument) and a volumetric increment, one more step ends on the cone of the law at
//     that step's trial pressure, and the return changed the mean stress (the plastic
//     compaction of psi);
//  3. at zero shear rate (a volumetric increment and a spin, from a stress beyond the cone)
//     the update with the rate law is the constant law's update, bit for bit (the friction at
//     rest and the static k_c are the model's own cone), and cone_of_tangent of the static
//     angle and a cohesion is the model's cone to 1e-15;
//  4. the checks of MaterialParameters: refused for a linear elastic or finite-strain model,
//     phi = 0, a 'Friction angle at high rate' below the 'Friction angle', a non-positive reference
//     number, grain diameter, grain density or fluid viscosity; a negative dilatancy is
//     checked for well-posedness at phi_2.
// Exits non-zero on failure.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <limits>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/material.h>
#include <string>
#include <vector>

using namespace slidewave::materials;
using unit_check::check;

namespace
{
  MaterialParameters
  beads(const FrictionLaw law, const double cohesion = 0., const double dilatancy = 0.)
  {
    MaterialParameters m;
    m.name                      = "beads";
    m.model                     = MaterialModel::drucker_prager;
    m.youngs_modulus            = 1e6;
    m.poisson_ratio             = 0.3;
    m.friction_angle            = 20.9;
    m.high_rate_friction_angle  = 32.76;
    m.cohesion                  = cohesion;
    m.dilatancy_angle           = dilatancy;
    m.friction_law              = law;
    m.reference_inertial_number = 0.279;
    m.reference_viscous_number  = 0.005;
    m.grain_diameter            = 0.5e-3;
    m.grain_density             = 2500.;
    m.fluid_viscosity           = 0.012;
    return m;
  }

  double
  root_j2(const dealii::SymmetricTensor<2, 3> &s)
  {
    const dealii::SymmetricTensor<2, 3> d = dealii::deviator(s);
    return std::sqrt(0.5 * (d * d));
  }

  /** The closed form of the law at rate number @p x. */
  double
  law(const MaterialParameters &m, const double x, const double x0)
  {
    const double mu_s = std::tan(m.friction_angle * M_PI / 180.);
    const double mu_2 = std::tan(m.high_rate_friction_angle * M_PI / 180.);
    return mu_s + (mu_2 - mu_s) / (1. + x0 / x);
  }

  /** The shear rate that gives rate number @p x at pressure @p p. */
  double
  rate_of(const MaterialParameters &m, const double x, const double p)
  {
    return m.friction_law == FrictionLaw::inertial ?
             x / (m.grain_diameter * std::sqrt(m.grain_density / p)) :
             x * p / m.fluid_viscosity;
  }

  /** The stress after a simple shear at rate @p rate to a shear strain of 0.05, from -p0. */
  dealii::SymmetricTensor<2, 3>
  sheared(const Material &material, const double rate, const double p0)
  {
    const double                  dt      = 1e-4;
    dealii::SymmetricTensor<2, 3> stress  = -p0 * dealii::unit_symmetric_tensor<3>();
    double                        plastic = 0.;
    dealii::SymmetricTensor<2, 3> increment;
    increment[0][1]          = 0.5 * rate * dt;
    const unsigned int steps = static_cast<unsigned int>(std::ceil(0.05 / (rate * dt)));
    for (unsigned int k = 0; k < steps; ++k)
      material.update_stress_at_rate(
        stress, increment, 0., plastic, std::numeric_limits<double>::quiet_NaN(), dt);
    return stress;
  }
} // namespace

int
main()
{
  std::printf("1. the law against its closed form\n");
  for (const FrictionLaw kind : {FrictionLaw::inertial, FrictionLaw::viscous})
    {
      const MaterialParameters m = beads(kind);
      const Material           material(m);
      const double             x0
        = kind == FrictionLaw::inertial ? m.reference_inertial_number : m.reference_viscous_number;
      const double p    = 2e3;
      const double mu_s = std::tan(m.friction_angle * M_PI / 180.);
      const double mu_2 = std::tan(m.high_rate_friction_angle * M_PI / 180.);
      std::printf(" %s\n", kind == FrictionLaw::inertial ? "inertial" : "viscous");
      check(material.friction_tangent(0., p) == mu_s, "at rest: mu_s");
      check(material.friction_tangent(1., 0.) == mu_s && material.friction_tangent(1., -5.) == mu_s,
            "shearing without pressure (p' <= 0): mu_s");
      check(material.friction_tangent(1., 1e-320) == mu_2,
            "a pressure so small that X overflows: mu_2");
      check(std::abs(material.friction_tangent(rate_of(m, x0, p), p) - 0.5 * (mu_s + mu_2)) < 1e-14,
            "at X = X_0: halfway");
      double worst = 0.;
      for (const double f : {0.01, 0.3, 10.})
        {
          const double x = f * x0;
          worst
            = std::max(worst,
                       std::abs(material.friction_tangent(rate_of(m, x, p), p) - law(m, x, x0)));
        }
      std::printf("  largest difference from the closed form: %.1e\n", worst);
      check(worst < 1e-14, "X = 0.01, 0.3, 10 X_0 within 1e-14");
    }

  std::printf("2. simple shear at a constant rate: the stress on the rate's cone\n");
  for (const double cohesion : {0., 2e3})
    for (const FrictionLaw kind : {FrictionLaw::inertial, FrictionLaw::viscous})
      {
        const MaterialParameters m = beads(kind, cohesion);
        const Material           material(m);
        const double             p0 = 1e4;
        const double             x0 = kind == FrictionLaw::inertial ? m.reference_inertial_number :
                                                                      m.reference_viscous_number;
        const double             k_c
          = DruckerPrager::cone_of_tangent(std::tan(m.friction_angle * M_PI / 180.), cohesion).k_c;
        std::printf(" %s, c = %g Pa: X / X_0, sqrt(J2) / p0, (3 alpha_phi p0 + k_c) / p0\n",
                    kind == FrictionLaw::inertial ? "inertial" : "viscous",
                    cohesion);
        double worst = 0., previous = 0.;
        bool   rising = true;
        for (const double f : {1e-4 / 0.279, 0.1, 1., 10., 10. / 0.279})
          {
            const double x     = f * x0;
            const double ratio = root_j2(sheared(material, rate_of(m, x, p0), p0)) / p0;
            const double exact
              = (3. * DruckerPrager::cone_of_tangent(law(m, x, x0), 0.).alpha_phi * p0 + k_c) / p0;
            std::printf("  %9.3e  %.12f  %.12f\n", f, ratio, exact);
            worst    = std::max(worst, std::abs(ratio - exact));
            rising   = rising && ratio > previous;
            previous = ratio;
          }
        check(worst < 1e-12, "on the cone of the rate's friction within 1e-12");
        check(rising, "the stress ratio rises with the rate");
      }
  {
    // psi = -5 deg through the NaN argument, a cohesion, and a step that also compresses.
    const MaterialParameters      m = beads(FrictionLaw::inertial, 2e3, -5.);
    const Material                material(m);
    const double                  rate   = rate_of(m, 0.3, 1e4);
    const double                  dt     = 1e-4;
    dealii::SymmetricTensor<2, 3> stress = sheared(material, rate, 1e4), increment;
    increment[0][1]                      = 0.5 * rate * dt;
    increment[0][0] = increment[1][1] = -2e-4;
    const dealii::SymmetricTensor<2, 3> trial
      = stress + material.elasticity().stress_increment(increment);
    const dealii::SymmetricTensor<2, 3> e = dealii::deviator(increment);
    const double                        tangent
      = material.friction_tangent(std::sqrt(2. * (e * e)) / dt, -dealii::trace(trial) / 3.);
    const double alpha = DruckerPrager::cone_of_tangent(tangent, 0.).alpha_phi;
    const double k_c
      = DruckerPrager::cone_of_tangent(std::tan(m.friction_angle * M_PI / 180.), 2e3).k_c;
    double plastic = 0.;
    material.update_stress_at_rate(
      stress, increment, 0., plastic, std::numeric_limits<double>::quiet_NaN(), dt);
    const double f = alpha * dealii::trace(stress) + root_j2(stress) - k_c;
    std::printf(" psi = -5 deg, c = 2 kPa, a compressing step: f on the law's cone %.1e Pa, the "
                "mean stress moved by the return %.3f Pa\n",
                std::abs(f) < 1e-9 ? 0. : f,
                dealii::trace(stress - trial) / 3.);
    check(std::abs(f) < 1e-9 * 1e4, "on the cone of the step's trial pressure");
    check(std::abs(dealii::trace(stress - trial)) > 1e-3,
          "the return moved the mean stress (psi = -5 deg)");
  }

  std::printf("3. at zero shear rate the rate law is the constant law\n");
  {
    const MaterialParameters with_rate = beads(FrictionLaw::inertial, 2e3, -5.);
    MaterialParameters       constant  = with_rate;
    constant.friction_law              = FrictionLaw::constant;
    const Material                a_material(with_rate), b_material(constant);
    dealii::SymmetricTensor<2, 3> a = -1e4 * dealii::unit_symmetric_tensor<3>(), increment;
    a[0][1]                         = 8e3; // beyond the cone
    dealii::SymmetricTensor<2, 3> b = a;
    increment[0][0] = increment[1][1] = increment[2][2] = -1e-3;
    double ea = 0., eb = 0.;
    a_material.update_stress_at_rate(
      a, increment, 2e-3, ea, std::numeric_limits<double>::quiet_NaN(), 1e-4);
    b_material.update_stress(b, increment, 2e-3, eb);
    check(a == b && ea == eb && ea > 0., "the same plastic update, bit for bit");
    const DruckerPrager dp(1e6, 0.3, 20.9, 2e4, 0., 0.);
    const Cone          c = DruckerPrager::cone_of_tangent(std::tan(20.9 * M_PI / 180.), 2e4);
    check(std::abs(c.alpha_phi - dp.alpha_phi()) < 1e-15
            && std::abs(c.k_c - dp.k_c()) < 1e-15 * dp.k_c(),
          "cone_of_tangent of the static angle and cohesion is the model's cone");
  }

  std::printf("4. refused parameters\n");
  {
    const auto parse = [](const std::vector<std::pair<std::string, std::string>> &entries) {
      dealii::ParameterHandler prm;
      MaterialParameters::declare_parameters(prm);
      prm.set("Name", "beads");
      prm.set("Friction angle", "25");
      for (const auto &[key, value] : entries)
        prm.set(key, value);
      MaterialParameters m;
      m.parse_parameters(prm, "Material points/Material 1");
      return m;
    };
    check(parse({{"Friction law", "inertial"}}).friction_law == FrictionLaw::inertial,
          "'inertial' with the defaults is read");
    check(unit_check::refused([&] {
            parse({{"Friction law", "viscous"}, {"Model", "linear elastic"}});
          }),
          "refused: linear elastic");
    check(unit_check::refused([&] {
            parse({{"Friction law", "inertial"}, {"Model", "hencky drucker prager"}});
          }),
          "refused: hencky drucker prager");
    check(unit_check::refused([&] {
            parse({{"Friction law", "inertial"}, {"Friction angle at high rate", "20"}});
          }),
          "refused: phi_2 below phi");
    check(unit_check::refused([&] {
            parse({{"Friction law", "inertial"}, {"Friction angle", "0"}});
          }),
          "refused: no friction at rest (phi = 0)");
    for (const char *entry : {"Reference inertial number", "Grain diameter", "Grain density"})
      check(unit_check::refused([&] {
              parse({{"Friction law", "inertial"}, {entry, "0"}});
            }),
            (std::string("refused: ") + entry + " = 0").c_str());
    for (const char *entry : {"Reference viscous number", "Fluid viscosity"})
      check(unit_check::refused([&] {
              parse({{"Friction law", "viscous"}, {entry, "-1"}});
            }),
            (std::string("refused: ") + entry + " = -1").c_str());
    check(!unit_check::refused([&] {
      parse({{"Friction law", "viscous"}, {"Grain diameter", "0"}});
    }),
          "'viscous' does not need the grain diameter");
    // nu = 0.45: K = 9.7 G; psi = -10 deg is well posed at phi = 25 deg (G + 9 K alpha_phi
    // alpha_psi = 0.31 G) but not at phi_2 = 60 deg (-0.29 G).
    check(!unit_check::refused([&] {
      parse({{"Poisson ratio", "0.45"}, {"Dilatancy angle", "-10"}});
    }),
          "psi = -10 deg at nu = 0.45 with the constant law");
    check(unit_check::refused([&] {
            parse({{"Poisson ratio", "0.45"},
                   {"Dilatancy angle", "-10"},
                   {"Friction law", "inertial"},
                   {"Friction angle at high rate", "60"}});
          }),
          "refused: the same psi ill-posed at phi_2 = 60 deg");
  }

  std::printf("%s\n", unit_check::all_passed ? "all passed" : "FAILED");
  return unit_check::all_passed ? 0 : 1;
}
