// The Drucker-Prager model with tension cutoff (paper 000, Eqs. 2-4; matching
// in VERIFICATION.md): plane-strain parameters for phi = 30 degrees, c = 10
// kPa; elastic unloading; the return on the cone (on the surface, Lode
// direction kept, closest point in the energy norm for psi = phi, consistent);
// the apex; the tension cutoff and the corner where it meets the cone; phi = 0
// (undrained clay, s_u = c in plane strain); psi = 0 (no plastic volume
// change). E = 10 MPa, nu = 0.3 unless said. Stresses in Pa, tension positive.
// Small errors are checked in the program and printed as verdicts; the program
// exits non-zero when a check fails.
#include <cmath>
#include <cstdio>
#include <deal.II/base/parameter_handler.h>
#include <initializer_list>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/material.h>

using dealii::SymmetricTensor;
using namespace slidewave::materials;

namespace
{
  bool all_passed = true;

  void
  check(const bool condition, const char *what)
  {
    std::printf("%s: %s\n", what, condition ? "yes" : "no");
    all_passed = all_passed && condition;
  }

  void
  print(const char *label, const SymmetricTensor<2, 3> &t)
  {
    std::printf("%s: xx = %.6f  yy = %.6f  zz = %.6f  xy = %.6f\n",
                label,
                t[0][0],
                t[1][1],
                t[2][2],
                t[0][1]);
  }

  SymmetricTensor<2, 3>
  stress(const double xx, const double yy, const double zz, const double xy)
  {
    SymmetricTensor<2, 3> t;
    t[0][0] = xx;
    t[1][1] = yy;
    t[2][2] = zz;
    t[0][1] = xy;
    return t;
  }

  double
  without_rounding_noise(const double strain)
  {
    return std::abs(strain) < 1e-15 ? 0. : strain;
  }

  double
  norm(const SymmetricTensor<2, 3> &t)
  {
    return std::sqrt(t * t);
  }

  double
  mean_stress(const SymmetricTensor<2, 3> &t)
  {
    return dealii::trace(t) / 3.;
  }

  double
  root_j2(const SymmetricTensor<2, 3> &t)
  {
    const SymmetricTensor<2, 3> s = dealii::deviator(t);
    return std::sqrt(0.5 * (s * s));
  }

  /** cos(3 theta) of the Lode angle theta: 3 sqrt(3)/2 J3 / J2^(3/2). */
  double
  cos_3_lode(const SymmetricTensor<2, 3> &t)
  {
    const double q = root_j2(t);
    return 1.5 * std::sqrt(3.) * dealii::determinant(dealii::deviator(t)) / (q * q * q);
  }

  /** The unit deviator s / |s|. */
  SymmetricTensor<2, 3>
  deviatoric_direction(const SymmetricTensor<2, 3> &t)
  {
    const SymmetricTensor<2, 3> s = dealii::deviator(t);
    return s / norm(s);
  }

  /** |f| small relative to the terms of f. */
  bool
  on_yield_surface(const DruckerPrager &model, const SymmetricTensor<2, 3> &t)
  {
    const double scale = model.k_c() + std::abs(model.alpha_phi() * dealii::trace(t)) + root_j2(t);
    return std::abs(model.yield_function(t)) <= 1e-9 * scale;
  }

  /** The complementary energy of a stress difference, d : D^-1 : d. */
  double
  energy(const DruckerPrager &model, const SymmetricTensor<2, 3> &difference)
  {
    return difference * model.elasticity().strain_increment(difference);
  }

  const char *
  region_name(const ReturnRegion region)
  {
    switch (region)
      {
        case ReturnRegion::elastic:
          return "elastic";
        case ReturnRegion::cone:
          return "cone";
        case ReturnRegion::tension_cutoff:
          return "tension cutoff";
        case ReturnRegion::corner:
          return "corner";
      }
    return "?";
  }

  /** Returns @p trial with @p model, prints and checks what every return must
   * satisfy. */
  PlasticCorrection
  return_and_print(const DruckerPrager         &model,
                   const SymmetricTensor<2, 3> &trial,
                   SymmetricTensor<2, 3>       &returned)
  {
    returned                           = trial;
    const PlasticCorrection correction = model.return_to_yield_surface(returned);
    print("trial   ", trial);
    print("returned", returned);
    std::printf("region: %s\n", region_name(correction.region));
    std::printf("p: %.6f -> %.6f  sqrt(J2): %.6f -> %.6f\n",
                mean_stress(trial),
                mean_stress(returned),
                root_j2(trial),
                root_j2(returned));
    std::printf("plastic volumetric strain = %.9f  equivalent plastic strain = %.9f\n",
                // rounding noise (~1e-20) printed as 0, so that its sign does not show
                without_rounding_noise(dealii::trace(correction.plastic_strain_increment)),
                correction.equivalent_plastic_strain_increment);
    check(model.yield_function(returned) <= 1e-9 * (model.k_c() + root_j2(trial))
            && mean_stress(returned)
                 <= model.tension_cutoff() + 1e-12 * (model.tension_cutoff() + norm(trial)),
          "returned stress admissible (f <= 0, p <= T)");
    // A second update with zero strain increment must do nothing.
    SymmetricTensor<2, 3>   again          = returned;
    double                  plastic_strain = 0.;
    const PlasticCorrection second
      = model.update_stress(again, SymmetricTensor<2, 3>(), plastic_strain);
    check(second.region == ReturnRegion::elastic && again == returned && plastic_strain == 0.,
          "consistent: a second update with zero strain increment does nothing");
    return correction;
  }
} // namespace

int
main()
{
  const double E = 1e7, nu = 0.3, phi = 30., c = 1e4;

  std::printf("* Plane-strain matching, phi = 30 degrees, c = 10 kPa\n");
  const DruckerPrager associated(E, nu, phi, c, phi, 1e6);
  const double        K = associated.elasticity().bulk_modulus();
  const double        G = associated.elasticity().shear_modulus();
  std::printf("alpha_phi = %.9f  (tan 30 / sqrt(13) = %.9f)\n",
              associated.alpha_phi(),
              std::tan(M_PI / 6.) / std::sqrt(13.));
  std::printf("k_c = %.6f Pa  (3 c / sqrt(13) = %.6f)\n",
              associated.k_c(),
              3. * c / std::sqrt(13.));
  std::printf("alpha_psi (psi = 30) = %.9f\n", associated.alpha_psi());
  std::printf("apex mean stress c cot(phi) = %.6f Pa\n", associated.apex_mean_stress());

  std::printf("\n* Associated return on the cone (psi = phi = 30)\n");
  const SymmetricTensor<2, 3> trial = stress(-6e4, -2e4, -4.5e4, 2.5e4);
  SymmetricTensor<2, 3>       on_cone;
  const PlasticCorrection     cone = return_and_print(associated, trial, on_cone);
  check(cone.region == ReturnRegion::cone, "region is the cone");
  check(on_yield_surface(associated, on_cone), "f(sigma) after return = 0 within 1e-9 relative");
  std::printf("cos(3 Lode angle): %.9f -> %.9f\n", cos_3_lode(trial), cos_3_lode(on_cone));
  check(norm(deviatoric_direction(on_cone) - deviatoric_direction(trial)) < 1e-12,
        "deviator keeps its direction (Lode angle) within 1e-12");
  const double dlambda = associated.yield_function(trial)
                         / (G + 9. * K * associated.alpha_phi() * associated.alpha_psi());
  std::printf("dlambda = f_trial / (G + 9 K alpha_phi alpha_psi) = %.9f\n", dlambda);
  check(std::abs(cone.equivalent_plastic_strain_increment - dlambda / std::sqrt(3.))
          < 1e-12 * dlambda,
        "equivalent plastic strain increment = dlambda / sqrt(3) within 1e-12 "
        "relative");
  // Normality: the plastic strain is dlambda times the gradient of f at the
  // returned stress.
  const SymmetricTensor<2, 3> gradient = associated.alpha_phi() * dealii::unit_symmetric_tensor<3>()
                                         + dealii::deviator(on_cone) / (2. * root_j2(on_cone));
  check(norm(cone.plastic_strain_increment - dlambda * gradient)
          < 1e-10 * norm(cone.plastic_strain_increment),
        "plastic strain = dlambda df/dsigma at the returned stress within "
        "1e-10 relative");
  // Closest point: no other point of the yield surface nearby is closer to the
  // trial stress in the energy norm. Neighbours: other mean stresses along the
  // cone, and deviators turned towards a second deviatoric direction, all put
  // back on f = 0.
  {
    const double                distance = energy(associated, trial - on_cone);
    const SymmetricTensor<2, 3> s_hat    = deviatoric_direction(on_cone);
    SymmetricTensor<2, 3>       other    = dealii::deviator(stress(0., 0., 1., 0.3));
    other                                = other - (other * s_hat) * s_hat;
    other /= norm(other);
    unsigned int n_points = 0, n_closer = 0;
    for (const double dp : {-2e3, -5e2, -1e2, -1., 1., 1e2, 5e2, 2e3})
      for (const double turn : {-0.1, -0.01, 0., 0.01, 0.1})
        {
          const double          p         = mean_stress(on_cone) + dp;
          const double          q         = associated.k_c() - 3. * associated.alpha_phi() * p;
          SymmetricTensor<2, 3> direction = std::cos(turn) * s_hat + std::sin(turn) * other;
          // |s| = sqrt(2) sqrt(J2)
          const SymmetricTensor<2, 3> neighbour
            = p * dealii::unit_symmetric_tensor<3>() + std::sqrt(2.) * q * direction;
          ++n_points;
          if (energy(associated, trial - neighbour) < distance)
            ++n_closer;
        }
    std::printf("neighbours on the yield surface: %u, closer to the trial stress: %u\n",
                n_points,
                n_closer);
    check(n_closer == 0, "closest point projection in the energy norm");
  }

  std::printf("\n* Elastic unloading from the cone: shear strain increment "
              "eps_xy = -1e-3\n");
  {
    SymmetricTensor<2, 3> unloaded = on_cone;
    SymmetricTensor<2, 3> strain_increment;
    strain_increment[0][1]                     = -1e-3;
    const SymmetricTensor<2, 3> expected       = on_cone + 2. * G * strain_increment;
    double                      plastic_strain = 0.5;
    const PlasticCorrection     unloading
      = associated.update_stress(unloaded, strain_increment, plastic_strain);
    print("stress", unloaded);
    std::printf("f = %.6f\n", associated.yield_function(unloaded));
    check(unloading.region == ReturnRegion::elastic && unloaded == expected && plastic_strain == 0.5
            && norm(unloading.plastic_strain_increment) == 0.,
          "trial inside: stress = trial, no plastic strain");
  }

  std::printf("\n* Non-associated flow with psi = 0: same trial stress\n");
  {
    const DruckerPrager     non_associated(E, nu, phi, c, 0., 1e6);
    SymmetricTensor<2, 3>   returned;
    const PlasticCorrection correction = return_and_print(non_associated, trial, returned);
    check(correction.region == ReturnRegion::cone, "region is the cone");
    check(on_yield_surface(non_associated, returned),
          "f(sigma) after return = 0 within 1e-9 relative");
    check(std::abs(dealii::trace(correction.plastic_strain_increment))
            < 1e-12 * norm(correction.plastic_strain_increment),
          "no plastic volume change within 1e-12 relative");
    check(std::abs(mean_stress(returned) - mean_stress(trial))
            < 1e-12 * std::abs(mean_stress(trial)),
          "mean stress unchanged within 1e-12 relative");
  }

  std::printf("\n* Non-associated flow with psi = 10: dilatancy ratio\n");
  {
    const DruckerPrager     dilatant(E, nu, phi, c, 10., 1e6);
    SymmetricTensor<2, 3>   returned;
    const PlasticCorrection correction = return_and_print(dilatant, trial, returned);
    check(on_yield_surface(dilatant, returned), "f(sigma) after return = 0 within 1e-9 relative");
    const double ratio = dealii::trace(correction.plastic_strain_increment)
                         / norm(dealii::deviator(correction.plastic_strain_increment));
    std::printf("tr(deps_p) / |dev(deps_p)| = %.9f  3 sqrt(2) alpha_psi = %.9f\n",
                ratio,
                3. * std::sqrt(2.) * dilatant.alpha_psi());
    check(std::abs(ratio - 3. * std::sqrt(2.) * dilatant.alpha_psi()) < 1e-10,
          "plastic volume change follows the potential g within 1e-10");
  }

  std::printf("\n* Non-associated flow with psi = -10: compaction under shear\n");
  {
    // A loose soil's potential: the plastic volume change is negative (tension positive),
    // with the same ratio to the deviatoric part as for psi = +10, and the return stays on
    // the cone (G + 9 K alpha_phi alpha_psi > 0).
    const DruckerPrager     compacting(E, nu, phi, c, -10., 1e6);
    SymmetricTensor<2, 3>   returned;
    const PlasticCorrection correction = return_and_print(compacting, trial, returned);
    check(correction.region == ReturnRegion::cone, "region is the cone");
    check(on_yield_surface(compacting, returned), "f(sigma) after return = 0 within 1e-9 relative");
    const double ratio = dealii::trace(correction.plastic_strain_increment)
                         / norm(dealii::deviator(correction.plastic_strain_increment));
    std::printf("tr(deps_p) / |dev(deps_p)| = %.9f  3 sqrt(2) alpha_psi = %.9f\n",
                ratio,
                3. * std::sqrt(2.) * compacting.alpha_psi());
    check(ratio < 0. && std::abs(ratio - 3. * std::sqrt(2.) * compacting.alpha_psi()) < 1e-10,
          "plastic volume decreases, following the potential g within 1e-10");
    check(mean_stress(returned) > mean_stress(trial),
          "the compaction relaxes the mean compression (p rises toward tension)");
  }

  std::printf("\n* Apex: strongly tensile trial stress, cutoff above the apex\n");
  for (const double psi : {30., 0.})
    {
      std::printf("psi = %.0f\n", psi);
      const DruckerPrager     model(E, nu, phi, c, psi, 1e6);
      SymmetricTensor<2, 3>   returned;
      const PlasticCorrection correction
        = return_and_print(model, stress(5e4, 4e4, 4.5e4, 5e3), returned);
      check(correction.region == ReturnRegion::corner, "region is the corner (apex)");
      check(root_j2(returned) < 1e-12 * model.k_c()
              && std::abs(dealii::trace(returned) - model.k_c() / model.alpha_phi())
                   < 1e-12 * model.k_c() / model.alpha_phi(),
            "s = 0 and I1 = k_c / alpha_phi within 1e-12 relative");
    }

  std::printf("\n* Tension cutoff T = 5 kPa, below the apex (17.32 kPa), psi = 30\n");
  {
    const DruckerPrager         model(E, nu, phi, c, phi, 5e3);
    SymmetricTensor<2, 3>       returned;
    const SymmetricTensor<2, 3> tensile    = stress(9e3, 7e3, 8e3, 5e2);
    const PlasticCorrection     correction = return_and_print(model, tensile, returned);
    check(correction.region == ReturnRegion::tension_cutoff, "region is the tension cutoff");
    check(std::abs(mean_stress(returned) - 5e3) < 1e-12 * 5e3
            && norm(dealii::deviator(returned) - dealii::deviator(tensile)) < 1e-12 * 5e3,
          "p = T and deviator unchanged within 1e-12 relative");
    check(correction.equivalent_plastic_strain_increment < 1e-15
            && std::abs(dealii::trace(correction.plastic_strain_increment) - 3e3 / K)
                 < 1e-12 * 3e3 / K,
          "purely volumetric plastic strain (p_trial - T) / K");

    std::printf("corner of cone and cutoff: larger shear\n");
    const SymmetricTensor<2, 3> sheared = stress(3e4, 1e4, 2e4, 8e3);
    const PlasticCorrection     corner  = return_and_print(model, sheared, returned);
    check(corner.region == ReturnRegion::corner, "region is the corner");
    std::printf("expected sqrt(J2) = k_c - 3 alpha_phi T = %.6f\n",
                model.k_c() - 3. * model.alpha_phi() * 5e3);
    check(on_yield_surface(model, returned) && std::abs(mean_stress(returned) - 5e3) < 1e-12 * 5e3,
          "on the cone and on the cutoff within 1e-9 relative");
    check(norm(deviatoric_direction(returned) - deviatoric_direction(sheared)) < 1e-12,
          "deviator keeps its direction within 1e-12");
  }

  std::printf("\n* phi = 0: undrained clay, E = 1 MPa, nu = 0.4, c = s_u = 3.2 "
              "kPa, T = 0\n");
  {
    const DruckerPrager clay(1e6, 0.4, 0., 3.2e3, 0., 0.);
    std::printf("alpha_phi = %.9f  alpha_psi = %.9f  k_c = %.6f  apex: %s\n",
                clay.alpha_phi(),
                clay.alpha_psi(),
                clay.k_c(),
                std::isinf(clay.apex_mean_stress()) ? "none" : "finite");
    SymmetricTensor<2, 3> returned;
    // sigma_zz is the mean of the in-plane stresses, as in plane-strain plastic
    // flow.
    const SymmetricTensor<2, 3> compressed = stress(-3e4, -1e4, -2e4, 4e3);
    const PlasticCorrection     correction = return_and_print(clay, compressed, returned);
    check(correction.region == ReturnRegion::cone, "region is the cone (a cylinder)");
    check(std::abs(root_j2(returned) - 3.2e3) < 1e-12 * 3.2e3,
          "sqrt(J2) = k_c = c within 1e-12 relative");
    check(std::abs(mean_stress(returned) - mean_stress(compressed)) < 1e-12 * 2e4
            && std::abs(dealii::trace(correction.plastic_strain_increment))
                 < 1e-12 * norm(correction.plastic_strain_increment),
          "mean stress unchanged, no volumetric plastic strain, within 1e-12 "
          "relative");
    const double in_plane_shear = std::sqrt(std::pow(0.5 * (returned[0][0] - returned[1][1]), 2)
                                            + std::pow(returned[0][1], 2));
    std::printf("in-plane (sigma_1 - sigma_3) / 2 = %.6f (the undrained "
                "strength s_u = c)\n",
                in_plane_shear);

    std::printf("tensile mean stress on clay with T = 0\n");
    const PlasticCorrection cracked = return_and_print(clay, stress(3e3, 1e3, 2e3, 5e2), returned);
    check(cracked.region == ReturnRegion::tension_cutoff && std::abs(mean_stress(returned)) < 1e-12,
          "tension cutoff: p = 0");

    std::printf("phi = c = 0: an inviscid fluid\n");
    const DruckerPrager fluid(1e6, 0.4, 0., 0., 0., 0.);
    return_and_print(fluid, compressed, returned);
    check(root_j2(returned) < 1e-12 * 2e4, "deviator removed");
  }

  std::printf("\n* A Drucker-Prager Material with a spin: rotation, predictor, return\n");
  {
    dealii::ParameterHandler prm;
    MaterialParameters::declare_parameters(prm);
    prm.set("Name", "sand");
    prm.set("Friction angle", "30");
    prm.set("Dilatancy angle", "30");
    prm.set("Cohesion", "10000");
    prm.set("Tension cutoff", "1e6");
    MaterialParameters parameters;
    parameters.parse_parameters(prm, "Material");
    const Material material(parameters);
    std::printf("K + 4G/3 = %.6f (expected %.6f)\n", material.p_wave_modulus(), K + 4. * G / 3.);
    SymmetricTensor<2, 3> strain_increment;
    strain_increment[0][1]               = 5e-3;
    strain_increment[0][0]               = -1e-3;
    SymmetricTensor<2, 3> updated        = stress(-4e4, -3e4, -3.5e4, 5e3);
    SymmetricTensor<2, 3> expected       = updated;
    double                plastic_strain = 0., expected_plastic_strain = 0.;
    apply_jaumann_rotation(expected, 1e-3);
    associated.update_stress(expected, strain_increment, expected_plastic_strain);
    material.update_stress(updated, strain_increment, 1e-3, plastic_strain);
    print("updated stress", updated);
    std::printf("equivalent plastic strain = %.9f\n", plastic_strain);
    check(updated == expected && plastic_strain == expected_plastic_strain && plastic_strain > 0.,
          "same as rotation followed by DruckerPrager::update_stress, with "
          "plastic flow");
  }

  std::printf("\n%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
