// Hooke's law in plane strain and the Jaumann rotation of the stress (paper
// 000, Eqs. 2, 5 and 6). E = 10 MPa, nu = 0.3: K = 8.333333 MPa, G = 3.846154
// MPa, lambda = 5.769231 MPa. Checked: the stress of a uniaxial strain, of a
// pure shear and of a biaxial plane strain (sigma_zz = nu (sigma_xx +
// sigma_yy)), the inverse map, and that a small counterclockwise spin turns a
// uniaxial stress counterclockwise, keeps I1 exactly and J2 to second order
// (relative change 3 theta^2). Stresses in Pa, tension positive. Exits non-zero
// on failure.
#include <cmath>
#include <cstdio>
#include <deal.II/base/parameter_handler.h>
#include <initializer_list>
#include <slidewave/materials/linear_elastic.h>
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

  double
  max_abs(const SymmetricTensor<2, 3> &t)
  {
    double m = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        m = std::max(m, std::abs(t[i][j]));
    return m;
  }

  double
  j2(const SymmetricTensor<2, 3> &t)
  {
    const SymmetricTensor<2, 3> s = dealii::deviator(t);
    return 0.5 * (s * s);
  }

  /** R sigma R^T for a counterclockwise rotation by theta in the xy plane. */
  SymmetricTensor<2, 3>
  rotated(const SymmetricTensor<2, 3> &sigma, const double theta)
  {
    dealii::Tensor<2, 3> R;
    R[0][0] = std::cos(theta);
    R[0][1] = -std::sin(theta);
    R[1][0] = std::sin(theta);
    R[1][1] = std::cos(theta);
    R[2][2] = 1.;
    return dealii::symmetrize(R * dealii::Tensor<2, 3>(sigma) * dealii::transpose(R));
  }

  /** The angle [rad] in [0, pi) of the major principal direction in the xy
   * plane. */
  double
  principal_angle(const SymmetricTensor<2, 3> &sigma)
  {
    const double angle = 0.5 * std::atan2(2. * sigma[0][1], sigma[0][0] - sigma[1][1]);
    return angle < 0. ? angle + M_PI : angle;
  }
} // namespace

int
main()
{
  const LinearElastic elastic(1e7, 0.3);
  const double        K      = elastic.bulk_modulus();
  const double        G      = elastic.shear_modulus();
  const double        lambda = elastic.lame_lambda();
  std::printf(
    "K = %.6f  G = %.6f  lambda = %.6f  K + 4G/3 = %.6f\n", K, G, lambda, elastic.p_wave_modulus());

  std::printf("\n* Uniaxial strain eps_xx = 1e-3\n");
  SymmetricTensor<2, 3> strain;
  strain[0][0]                         = 1e-3;
  const SymmetricTensor<2, 3> uniaxial = elastic.stress_increment(strain);
  print("stress", uniaxial);
  std::printf("expected: xx = (lambda + 2G) eps = %.6f  yy = zz = lambda eps = %.6f\n",
              (lambda + 2. * G) * 1e-3,
              lambda * 1e-3);
  check(std::abs(uniaxial[0][0] - (lambda + 2. * G) * 1e-3) < 1e-9
          && std::abs(uniaxial[1][1] - lambda * 1e-3) < 1e-9
          && std::abs(uniaxial[2][2] - lambda * 1e-3) < 1e-9 && uniaxial[0][1] == 0.,
        "uniaxial strain stress matches Hooke's law within 1e-9 Pa");

  std::printf("\n* Pure shear eps_xy = 1e-3 (engineering shear strain 2e-3)\n");
  strain                            = 0;
  strain[0][1]                      = 1e-3;
  const SymmetricTensor<2, 3> shear = elastic.stress_increment(strain);
  print("stress", shear);
  std::printf("expected: xy = 2 G eps_xy = %.6f, no normal stress\n", 2. * G * 1e-3);
  check(std::abs(shear[0][1] - 2. * G * 1e-3) < 1e-9 && shear[0][0] == 0. && shear[1][1] == 0.
          && shear[2][2] == 0.,
        "pure shear gives shear stress only, within 1e-9 Pa");

  std::printf("\n* Plane strain eps_xx = 1e-3, eps_yy = -4e-4, eps_xy = 2e-4, "
              "eps_zz = 0\n");
  strain                            = 0;
  strain[0][0]                      = 1e-3;
  strain[1][1]                      = -4e-4;
  strain[0][1]                      = 2e-4;
  const SymmetricTensor<2, 3> plane = elastic.stress_increment(strain);
  print("stress", plane);
  std::printf("nu (sigma_xx + sigma_yy) = %.6f\n", 0.3 * (plane[0][0] + plane[1][1]));
  check(std::abs(plane[2][2] - 0.3 * (plane[0][0] + plane[1][1])) < 1e-12 * max_abs(plane),
        "sigma_zz = nu (sigma_xx + sigma_yy) within 1e-12 relative");
  check(max_abs(elastic.strain_increment(plane) - strain) < 1e-15,
        "strain_increment() inverts stress_increment() within 1e-15");

  std::printf("\n* Jaumann rotation of a uniaxial stress sigma_xx = 100 kPa\n");
  SymmetricTensor<2, 3> sigma;
  sigma[0][0] = 1e5;
  for (const double theta : {1e-3, 5e-4})
    {
      // A counterclockwise rotation by theta: v = Omega (-y, x), so the spin
      // increment W_xy = 1/2 (dv_x/dy - dv_y/dx) dt = -Omega dt = -theta.
      SymmetricTensor<2, 3> turned = sigma;
      apply_jaumann_rotation(turned, -theta);
      std::printf("theta = %.1e counterclockwise (W_xy = %.1e)\n", theta, -theta);
      print("  rotated stress", turned);
      print("  exact R sigma R^T", rotated(sigma, theta));
      std::printf("  principal direction / theta = %.6f\n", principal_angle(turned) / theta);
      std::printf("  max |difference to R sigma R^T| / (theta^2 |sigma|) = %.6f\n",
                  max_abs(turned - rotated(sigma, theta)) / (theta * theta * 1e5));
      check(std::abs(principal_angle(turned) / theta - 1.) < 1e-5,
            "  turned counterclockwise by theta within 1e-5 relative");
      check(max_abs(turned - rotated(sigma, theta)) < 1.01 * theta * theta * 1e5,
            "  first-order accurate: |difference| <= 1.01 theta^2 |sigma|");
      check(dealii::trace(turned) == dealii::trace(sigma), "  I1 unchanged exactly");
      std::printf("  (J2 after - J2 before) / (J2 theta^2) = %.6f\n",
                  (j2(turned) - j2(sigma)) / (j2(sigma) * theta * theta));
    }

  std::printf("\n* 1000 steps of theta = pi/2000: the uniaxial stress turns to "
              "the y axis\n");
  SymmetricTensor<2, 3> turned = sigma;
  for (unsigned int step = 0; step < 1000; ++step)
    apply_jaumann_rotation(turned, -M_PI / 2000.);
  std::printf("principal direction after the steps = %.6f degrees\n",
              principal_angle(turned) * 180. / M_PI);
  std::printf("relative drift of J2 (first-order integration, ~3 pi^2/4000) = %.6f\n",
              j2(turned) / j2(sigma) - 1.);
  check(std::abs(principal_angle(turned) - M_PI / 2.) < 1e-5,
        "principal direction at 90 degrees within 1e-5 rad");

  std::printf("\n* A linear elastic Material: rotation of the old stress, then Hooke\n");
  dealii::ParameterHandler prm;
  MaterialParameters::declare_parameters(prm);
  prm.set("Name", "rock");
  prm.set("Model", "linear elastic");
  prm.set("Density", "1800");
  prm.set("Young's modulus", "1e7");
  prm.set("Poisson ratio", "0.3");
  MaterialParameters parameters;
  parameters.parse_parameters(prm, "Material");
  const Material material(parameters);
  std::printf("density = %.6f  K + 4G/3 = %.6f\n", material.density(), material.p_wave_modulus());
  SymmetricTensor<2, 3> updated        = sigma;
  double                plastic_strain = 0.;
  const double          spin_increment = -1e-3;
  SymmetricTensor<2, 3> expected       = sigma;
  apply_jaumann_rotation(expected, spin_increment);
  expected += elastic.stress_increment(strain);
  material.update_stress(updated, strain, spin_increment, plastic_strain);
  print("updated stress", updated);
  check(max_abs(updated - expected) == 0. && plastic_strain == 0.,
        "update_stress = rotation then Hooke, no plastic strain");

  std::printf("\n%s\n", all_passed ? "all checks passed" : "SOME CHECKS FAILED");
  return all_passed ? 0 : 1;
}
