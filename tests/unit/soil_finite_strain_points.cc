// The finite-strain points' pieces (soil::FiniteStrainPoints, materials::HenckyDruckerPrager):
// (a) the closed-form 2 x 2 exponential of the increment f = exp(L dt) against a Taylor
//     series (of A / 2^m with |A / 2^m| <= 1/2, squared m times; m = 0 to 2 here, each
//     squaring doubles the series' rounding) for a step-sized gradient (the series
//     branch), a nilpotent one (simple shear, exp = I + A), real eigenvalues (cosh),
//     complex ones (a rotation, cos), and det exp(A) = exp(tr A);
// (b) b^e from a stress and back: kirchhoff_stress(elastic_left_cauchy_green(tau)) = tau
//     for a general plane-strain stress, and b^e = I for tau = 0;
// (c) one point's update: b^e, the Cauchy stress sigma = tau / J and the volume of a
//     point of a Hencky material under a step of uniaxial stretch, against the closed form;
// (d) a non-finite velocity gradient (a run that has failed) marks the point non-finite
//     for the guards instead of throwing on one rank.
// Each check prints its number and tolerance; exits non-zero when one fails.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <slidewave/soil/finite_strain_points.h>
#include <slidewave/soil/particle_properties.h>
#include <vector>

using dealii::Tensor;
using namespace slidewave;

namespace
{
  void
  verdict(const char *what, const double value, const double tolerance)
  {
    const bool pass = std::abs(value) <= tolerance;
    std::printf("%s: %s = %.1e (tolerance %.0e)\n", pass ? "PASS" : "FAIL", what, value, tolerance);
    unit_check::all_passed = unit_check::all_passed && pass;
  }

  /** exp(A): Taylor series of A / 2^m (norm below 1/2), squared m times. */
  Tensor<2, 2>
  series(const Tensor<2, 2> &A)
  {
    unsigned int m = 0;
    while (A.norm() / std::pow(2., m) > 0.5)
      ++m;
    const Tensor<2, 2> a = A / std::pow(2., m);
    Tensor<2, 2>       sum, term;
    sum[0][0] = sum[1][1] = term[0][0] = term[1][1] = 1.;
    for (unsigned int k = 1; k < 40; ++k)
      {
        term = term * a / static_cast<double>(k);
        sum += term;
      }
    for (unsigned int i = 0; i < m; ++i)
      sum = sum * sum;
    return sum;
  }
} // namespace



int
main()
{
  // (a)
  const std::vector<std::pair<const char *, Tensor<2, 2>>> cases{
    {"step-sized gradient", Tensor<2, 2>({{1e-4, 3e-4}, {-2e-4, -5e-5}})},
    {"simple shear", Tensor<2, 2>({{0., 0.7}, {0., 0.}})},
    {"real eigenvalues", Tensor<2, 2>({{0.3, 0.8}, {0.5, -0.6}})},
    {"rotation", Tensor<2, 2>({{0.1, -1.2}, {1.2, 0.1}})}};
  for (const auto &[name, A] : cases)
    {
      const Tensor<2, 2> f     = soil::FiniteStrainPoints::exponential(A);
      const Tensor<2, 2> exact = series(A);
      std::printf("%s:\n", name);
      verdict("  |exp(A) - series| / |series|", (f - exact).norm() / exact.norm(), 1e-14);
      verdict("  det exp(A) / exp(tr A) - 1",
              dealii::determinant(f) / std::exp(A[0][0] + A[1][1]) - 1.,
              1e-14);
    }

  // (b)
  const materials::HenckyDruckerPrager model(1e7, 0.3, 30., 1e4, 5.);
  dealii::SymmetricTensor<2, 3>        tau;
  tau[0][0]                             = -3e5;
  tau[1][1]                             = -1e5;
  tau[0][1]                             = 4e4;
  tau[2][2]                             = -2e5;
  const dealii::SymmetricTensor<2, 3> b = model.elastic_left_cauchy_green(tau);
  verdict("tau(b^e(tau)) - tau, relative",
          (model.kirchhoff_stress(b) - tau).norm() / tau.norm(),
          1e-13); // two 3 x 3 eigendecompositions (Jacobi), logs and exps

  verdict("b^e(0) - I",
          (model.elastic_left_cauchy_green(dealii::SymmetricTensor<2, 3>())
           - dealii::unit_symmetric_tensor<3>())
            .norm(),
          1e-15);

  // (c) a stretch of 2 % along x in one step of a stress-free point (elastic).
  materials::MaterialParameters material;
  material.model                       = materials::MaterialModel::hencky_drucker_prager;
  material.youngs_modulus              = 1e7;
  material.poisson_ratio               = 0.3;
  material.cohesion                    = 1e9;
  const unsigned int             first = soil::property::n_properties;
  const soil::FiniteStrainPoints points({material}, first);
  std::vector<double>            p(first + 4, 0.);
  points.initialize(p);
  p[soil::property::volume] = p[soil::property::initial_volume] = 1e-4;
  const double       stretch                                    = std::log(1.02);
  const Tensor<2, 2> L({{stretch, 0.}, {0., 0.}});
  points.update(dealii::make_array_view(p), L, 1., 0.);
  const double K = 1e7 / (3. * 0.4), G = 1e7 / 2.6;
  const double tau_xx = (K + 4. * G / 3.) * stretch, tau_yy = (K - 2. * G / 3.) * stretch;
  verdict("b^e_xx - 1.02^2", p[first] - 1.02 * 1.02, 1e-15);
  verdict("b^e_yy - 1, b^e_zz - 1",
          std::abs(p[first + 1] - 1.) + std::abs(p[first + 3] - 1.),
          1e-15);
  verdict("volume / 1.02e-4 - 1", p[soil::property::volume] / 1.02e-4 - 1., 1e-15);
  verdict("sigma_xx / (tau_xx / 1.02) - 1",
          p[soil::property::stress_xx] / (tau_xx / 1.02) - 1.,
          1e-14);
  verdict("sigma_yy / (tau_yy / 1.02) - 1",
          p[soil::property::stress_yy] / (tau_yy / 1.02) - 1.,
          1e-14);
  verdict("sigma_zz - sigma_yy", p[soil::property::stress_zz] - p[soil::property::stress_yy], 1e-9);

  // (d) a failed run's non-finite gradient: no exception (it would leave the other ranks
  // waiting), the point marked non-finite for the guards.
  bool thrown = false;
  try
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      points.update(dealii::make_array_view(p), Tensor<2, 2>({{nan, 0.}, {0., 0.}}), 1., 0.);
    }
  catch (...)
    {
      thrown = true;
    }
  std::printf("non-finite velocity gradient:\n");
  unit_check::check(!thrown, "no exception");
  unit_check::check(std::isnan(p[soil::property::stress_xx]) && std::isnan(p[first]),
                    "stress and b^e marked non-finite");
  return unit_check::finish();
}
