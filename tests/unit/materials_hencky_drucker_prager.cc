// Hencky elastoplasticity with Drucker-Prager of paper 002, section 2.2
// (materials::HenckyDruckerPrager): F = F^e F^p, b^e_trial = f b^e f^T,
// principal logarithmic strains, return mapping in principal space.
// E = 10 MPa, nu = 0.3, phi = 30 degrees, c = 10 kPa unless said; stresses in
// Pa, tension positive. Checked:
// (a) small strains: agrees with LinearElastic and the small-strain
//     DruckerPrager to O(strain^2), i.e. a relative difference O(strain);
// (b) a large rigid rotation of a stressed state rotates the Kirchhoff stress
//     exactly (no Jaumann drift), in one step and in 100 steps;
// (c) plastic loading: on the yield surface to rounding, the plastic flow
//     direction set by the dilatancy angle, psi = phi associated;
// (d) the apex return under tension;
// (e) a monotonic elastic path in 1000 small steps gives the stress of one
//     big step (hyperelastic, path independent).
// Each check prints PASS/FAIL with its number, tolerance and the reason for
// the tolerance. Exits non-zero when a check fails.
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <initializer_list>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/hencky_drucker_prager.h>
#include <slidewave/materials/linear_elastic.h>

using dealii::SymmetricTensor;
using dealii::Tensor;
using namespace slidewave::materials;

namespace
{
  constexpr double E   = 10e6;
  constexpr double nu  = 0.3;
  constexpr double phi = 30.;
  constexpr double c   = 10e3;

  void
  verdict(const char *what, const double value, const double tolerance, const char *why)
  {
    const bool pass = std::abs(value) <= tolerance;
    std::printf(
      "%s: %s = %.3e (tolerance %.0e: %s)\n", pass ? "PASS" : "FAIL", what, value, tolerance, why);
    unit_check::all_passed = unit_check::all_passed && pass;
  }

  void
  print(const char *label, const SymmetricTensor<2, 3> &t)
  {
    std::printf("%s: xx = %.3f  yy = %.3f  zz = %.3f  xy = %.3f  yz = %.3f  xz = %.3f\n",
                label,
                t[0][0],
                t[1][1],
                t[2][2],
                t[0][1],
                t[1][2],
                t[0][2]);
  }

  double
  norm(const SymmetricTensor<2, 3> &t)
  {
    return std::sqrt(t * t);
  }

  double
  root_j2(const SymmetricTensor<2, 3> &t)
  {
    const SymmetricTensor<2, 3> s = dealii::deviator(t);
    return std::sqrt(0.5 * (s * s));
  }

  double
  mean(const SymmetricTensor<2, 3> &t)
  {
    return dealii::trace(t) / 3.;
  }

  Tensor<2, 3>
  matrix(const std::initializer_list<double> rows)
  {
    Tensor<2, 3> m;
    unsigned int k = 0;
    for (const double v : rows)
      {
        m[k / 3][k % 3] = v;
        ++k;
      }
    return m;
  }

  SymmetricTensor<2, 3>
  left_cauchy_green(const Tensor<2, 3> &F)
  {
    return dealii::symmetrize(F * dealii::transpose(F));
  }

  /** R t R^T. */
  SymmetricTensor<2, 3>
  rotate(const SymmetricTensor<2, 3> &t, const Tensor<2, 3> &R)
  {
    return dealii::symmetrize(R * static_cast<Tensor<2, 3>>(t) * dealii::transpose(R));
  }

  /** The rotation by @p angle [rad] about the unit vector @p axis (Rodrigues). */
  Tensor<2, 3>
  rotation(const Tensor<1, 3> &axis, const double angle)
  {
    Tensor<2, 3> W;
    W[0][1] = -axis[2];
    W[0][2] = axis[1];
    W[1][0] = axis[2];
    W[1][2] = -axis[0];
    W[2][0] = -axis[1];
    W[2][1] = axis[0];
    return dealii::unit_symmetric_tensor<3>() + std::sin(angle) * W
           + (1. - std::cos(angle)) * W * W;
  }

  /** One step from b^e = @p b with the increment @p f; J of the total F is @p J. */
  HenckyStep
  step(const HenckyDruckerPrager &model,
       SymmetricTensor<2, 3>     &b,
       const Tensor<2, 3>        &f,
       const double               J)
  {
    double plastic = 0.;
    return model.update(b, f, J, plastic);
  }

  const char *
  region_name(const HenckyReturn region)
  {
    switch (region)
      {
        case HenckyReturn::elastic:
          return "elastic";
        case HenckyReturn::cone:
          return "cone";
        case HenckyReturn::apex:
          return "apex";
      }
    return "?";
  }

  /** |f| relative to the terms of f. */
  double
  relative_yield(const HenckyDruckerPrager &model, const SymmetricTensor<2, 3> &tau)
  {
    return model.yield_function(tau)
           / (model.k_c() + std::abs(model.alpha_phi() * dealii::trace(tau)) + root_j2(tau));
  }



  void
  small_strains()
  {
    std::printf("* (a) Small strains against the small-strain models\n");
    std::printf(
      "Elastic (c = 1e12 Pa, never yields), plane strain, strain s (-1, 0.5, 0; xy 0.4)\n");
    const HenckyDruckerPrager elastic(E, nu, phi, 1e12, 0.);
    const LinearElastic       hooke(E, nu);
    const Tensor<2, 3>        H        = matrix({-1., 0.4, 0., 0.4, 0.5, 0., 0., 0., 0.});
    double                    previous = 0.;
    for (const double s : {1e-3, 1e-4, 1e-5})
      {
        SymmetricTensor<2, 3>       b          = dealii::unit_symmetric_tensor<3>();
        const Tensor<2, 3>          F          = dealii::unit_symmetric_tensor<3>() + s * H;
        const HenckyStep            r          = step(elastic, b, F, dealii::determinant(F));
        const SymmetricTensor<2, 3> linear     = hooke.stress_increment(dealii::symmetrize(s * H));
        const double                difference = norm(r.cauchy_stress - linear) / norm(linear);
        std::printf("s = %.0e: |sigma_Hencky - sigma_Hooke| / |sigma_Hooke| = %.4e  (/ s = %.4f)\n",
                    s,
                    difference,
                    difference / s);
        verdict("  relative difference / s",
                difference / s,
                3.,
                "second order: the log strain, sigma = tau / J and the geometry each differ "
                "by O(s^2), with coefficients of order one");
        if (previous > 0.)
          verdict("  order of the difference in s minus 1 (log10 of its drop per decade - 1)",
                  std::log10(previous / difference) - 1.,
                  0.02,
                  "the O(s^3) terms change the drop by 1e-2 at most for s <= 1e-3");
        previous = difference;
      }

    std::printf("Plastic, c = 0 (cone through the origin: yields at every s), psi = 10, strain "
                "s (-1, -0.2, 0; xy 1)\n");
    const HenckyDruckerPrager hencky(E, nu, phi, 0., 10.);
    const DruckerPrager       small(E, nu, phi, 0., 10., 0.);
    const Tensor<2, 3>        P = matrix({-1., 1., 0., 1., -0.2, 0., 0., 0., 0.});
    previous                    = 0.;
    for (const double s : {1e-3, 1e-4, 1e-5})
      {
        SymmetricTensor<2, 3> b = dealii::unit_symmetric_tensor<3>();
        const Tensor<2, 3>    F = dealii::unit_symmetric_tensor<3>() + s * P;
        const HenckyStep      r = step(hencky, b, F, dealii::determinant(F));
        SymmetricTensor<2, 3> sigma;
        double                plastic = 0.;
        const auto   correction = small.update_stress(sigma, dealii::symmetrize(s * P), plastic);
        const double difference = norm(r.cauchy_stress - sigma) / norm(sigma);
        std::printf("s = %.0e: regions %s / %s  relative difference = %.4e  (/ s = %.4f)  "
                    "plastic strain %.6e / %.6e\n",
                    s,
                    region_name(r.region),
                    correction.region == ReturnRegion::cone ? "cone" : "other",
                    difference,
                    difference / s,
                    r.equivalent_plastic_strain_increment,
                    plastic);
        verdict("  relative difference / s", difference / s, 3., "second order, as above");
        verdict("  relative difference of the equivalent plastic strain / s",
                (r.equivalent_plastic_strain_increment - plastic) / plastic / s,
                3.,
                "second order, as above");
        if (previous > 0.)
          verdict("  order of the difference in s minus 1",
                  std::log10(previous / difference) - 1.,
                  0.02,
                  "as above");
        previous = difference;
      }
  }



  void
  rigid_rotation()
  {
    std::printf("\n* (b) Rigid rotation of a stressed state\n");
    const HenckyDruckerPrager model(E, nu, phi, c, 10.);
    // A stressed state on the cone: 3 % compression and 8 % shear, returned to the cone.
    SymmetricTensor<2, 3> b     = dealii::unit_symmetric_tensor<3>();
    const Tensor<2, 3>    F0    = matrix({0.97, 0.08, 0., 0., 0.99, 0., 0., 0., 1.});
    const HenckyStep      start = step(model, b, F0, dealii::determinant(F0));
    std::printf("initial state: region %s  p = %.3f  sqrt(J2) = %.3f  f / scale = %.2e\n",
                region_name(start.region),
                mean(start.kirchhoff_stress),
                root_j2(start.kirchhoff_stress),
                relative_yield(model, start.kirchhoff_stress));
    const SymmetricTensor<2, 3> tau0 = start.kirchhoff_stress;
    const double                J0   = dealii::determinant(F0);
    const double                j3   = dealii::determinant(dealii::deviator(tau0));

    Tensor<1, 3> axis_z;
    axis_z[2] = 1.;
    Tensor<1, 3> axis_skew;
    axis_skew[0] = 1.;
    axis_skew[1] = 2.;
    axis_skew[2] = 3.;
    axis_skew /= axis_skew.norm();
    struct Case
    {
      const char  *name;
      Tensor<1, 3> axis;
      double       angle;
      unsigned int steps;
    };
    for (const Case &rotation_case :
         {Case{"90 degrees about z, one step", axis_z, M_PI / 2, 1},
          Case{"90 degrees about z, 100 steps", axis_z, M_PI / 2, 100},
          Case{"170 degrees about (1,2,3), 100 steps", axis_skew, 170. * M_PI / 180., 100}})
      {
        SymmetricTensor<2, 3> be = b;
        const Tensor<2, 3>    increment
          = rotation(rotation_case.axis, rotation_case.angle / rotation_case.steps);
        HenckyStep r;
        bool       all_elastic = true;
        for (unsigned int k = 0; k < rotation_case.steps; ++k)
          {
            r           = step(model, be, increment, J0);
            all_elastic = all_elastic && r.region == HenckyReturn::elastic;
          }
        const Tensor<2, 3> R = rotation(rotation_case.axis, rotation_case.angle);
        std::printf("%s: all steps elastic: %s\n", rotation_case.name, all_elastic ? "yes" : "no");
        verdict("  |tau - R tau0 R^T| / |tau0|",
                norm(r.kirchhoff_stress - rotate(tau0, R)) / norm(tau0),
                1e-12,
                "f b f^T rounds b by ~1e-16 per step, an absolute error in the log strains "
                "that is ~3e-15 of strains of 3e-2: 100 steps");
        verdict("  relative change of I1",
                (dealii::trace(r.kirchhoff_stress) / dealii::trace(tau0) - 1.),
                1e-12,
                "rounding, as above");
        verdict("  relative change of J2",
                std::pow(root_j2(r.kirchhoff_stress) / root_j2(tau0), 2) - 1.,
                1e-12,
                "rounding, as above");
        verdict("  |f| / scale at the end (on the cone before the rotation)",
                relative_yield(model, r.kirchhoff_stress),
                1e-12,
                "rounding, as above");
        verdict("  relative change of J3",
                dealii::determinant(dealii::deviator(r.kirchhoff_stress)) / j3 - 1.,
                1e-11,
                "rounding, as above, three factors");
        verdict("  steps that were not elastic (a rotation must not yield)",
                all_elastic ? 0. : 1.,
                0.,
                "a yes/no check");
        verdict("  |sigma - tau / J0| / |sigma|",
                norm(r.cauchy_stress - r.kirchhoff_stress / J0) / norm(r.cauchy_stress),
                1e-15,
                "one division");
      }
    std::printf("(A hypoelastic update with the Jaumann rate rotates the stress only to "
                "O(dtheta^2) per step; here the rotation enters only through f b^e f^T.)\n");
  }


  double
  commutator(const SymmetricTensor<2, 3> &a, const SymmetricTensor<2, 3> &b)
  {
    const Tensor<2, 3> A = a;
    const Tensor<2, 3> B = b;
    return (A * B - B * A).norm() / (A.norm() * B.norm());
  }



  void
  plastic_loading()
  {
    std::printf("\n* (c) Plastic loading in one step: 5 %% compression, 10 %% shear, plane "
                "strain\n");
    const Tensor<2, 3>          f         = matrix({0.95, 0.10, 0., 0., 1., 0., 0., 0., 1.});
    const SymmetricTensor<2, 3> b_trial   = left_cauchy_green(f);
    const SymmetricTensor<2, 3> eps_trial = HenckyDruckerPrager::logarithmic_strain(b_trial);
    for (const double psi : {0., 10., phi})
      {
        const HenckyDruckerPrager model(E, nu, phi, c, psi);
        SymmetricTensor<2, 3>     b       = dealii::unit_symmetric_tensor<3>();
        double                    plastic = 0.;
        const HenckyStep          r       = model.update(b, f, dealii::determinant(f), plastic);
        std::printf("psi = %.0f: region %s  p: %.3f -> %.3f  sqrt(J2): %.3f -> %.3f\n",
                    psi,
                    region_name(r.region),
                    mean(model.kirchhoff_stress(b_trial)),
                    mean(r.kirchhoff_stress),
                    root_j2(model.kirchhoff_stress(b_trial)),
                    root_j2(r.kirchhoff_stress));
        print("  tau  ", r.kirchhoff_stress);
        print("  sigma", r.cauchy_stress);
        verdict("  region is not the cone (1) or is (0)",
                r.region == HenckyReturn::cone ? 0. : 1.,
                0.,
                "a yes/no check");
        verdict("  |f(tau)| / (k_c + |alpha_phi I1| + sqrt(J2))",
                relative_yield(model, r.kirchhoff_stress),
                1e-13,
                "tau is rebuilt from principal values: ~1e-16 of the stress per term");
        // The plastic strain from an independent decomposition of the new b^e.
        const SymmetricTensor<2, 3> eps            = HenckyDruckerPrager::logarithmic_strain(b);
        const SymmetricTensor<2, 3> plastic_strain = eps_trial - eps;
        verdict("  |(eps_trial - eps(b^e_new)) - dEps^p| / |dEps^p|",
                norm(plastic_strain - r.plastic_strain_increment) / norm(plastic_strain),
                1e-12,
                "strains of 1e-1 subtracted to 1e-2: rounding 1e-16 times 10, several steps");
        verdict("  |tau(b^e_new) - tau| / |tau|",
                norm(model.kirchhoff_stress(b) - r.kirchhoff_stress) / norm(r.kirchhoff_stress),
                1e-13,
                "one more eigen-decomposition, strains of 1e-1 for stresses 10 times smaller");
        verdict("  |b^e_new b^e_trial - b^e_trial b^e_new| (coaxial, trial axes kept)",
                commutator(b, b_trial),
                1e-14,
                "rounding of the products");
        const double ratio = dealii::trace(plastic_strain) / norm(dealii::deviator(plastic_strain));
        const double expected = 3. * std::sqrt(2.) * model.alpha_psi();
        std::printf("  plastic volumetric / deviatoric strain = %.9f  3 sqrt(2) alpha_psi = %.9f\n",
                    ratio,
                    expected);
        verdict("  tr(dEps^p) / |dev dEps^p| - 3 sqrt(2) alpha_psi",
                ratio - expected,
                1e-11,
                "strains of 1e-1 subtracted to 1e-2, as above");
        verdict("  equivalent plastic strain: relative difference of step and state",
                plastic / r.equivalent_plastic_strain_increment - 1.,
                1e-15,
                "the same number");
        if (psi == phi)
          {
            const SymmetricTensor<2, 3> normal
              = model.alpha_phi() * dealii::unit_symmetric_tensor<3>()
                + dealii::deviator(r.kirchhoff_stress) / (2. * root_j2(r.kirchhoff_stress));
            verdict("  associated: |dEps^p / |dEps^p| - n / |n||, n = df/dtau at the returned "
                    "tau",
                    norm(plastic_strain / norm(plastic_strain) - normal / norm(normal)),
                    1e-12,
                    "strains of 1e-1 subtracted to 1e-2, as above");
          }
        if (psi == 0.)
          verdict("  psi = 0 (the paper's potential g = sqrt(J2)): |tr dEps^p| / |dEps^p|",
                  dealii::trace(r.plastic_strain_increment) / norm(r.plastic_strain_increment),
                  1e-14,
                  "rounding");
        SymmetricTensor<2, 3> again = b;
        const HenckyStep      rest
          = step(model, again, dealii::unit_symmetric_tensor<3>(), dealii::determinant(f));
        verdict("  a second step with f = I: not elastic (1) or |tau change| / |tau|",
                rest.region != HenckyReturn::elastic ?
                  1. :
                  norm(rest.kirchhoff_stress - r.kirchhoff_stress) / norm(r.kirchhoff_stress),
                1e-13,
                "consistency: the returned state lies on the cone to rounding");
      }
  }



  void
  cylinder_return()
  {
    std::printf("\n* (c) phi = 0: the cone is the cylinder sqrt(J2) = c, no apex (1 %% "
                "stretch, 10 %% shear)\n");
    const HenckyDruckerPrager clay(E, nu, 0., c, 0.);
    const Tensor<2, 3>        f       = matrix({1.01, 0.1, 0., 0., 1.01, 0., 0., 0., 1.});
    SymmetricTensor<2, 3>     b       = dealii::unit_symmetric_tensor<3>();
    const double              p_trial = mean(clay.kirchhoff_stress(left_cauchy_green(f)));
    const HenckyStep          r       = step(clay, b, f, dealii::determinant(f));
    std::printf("region %s  p: %.6f -> %.6f  sqrt(J2) = %.6f\n",
                region_name(r.region),
                p_trial,
                mean(r.kirchhoff_stress),
                root_j2(r.kirchhoff_stress));
    verdict("  region is not the cone (1) or is (0)",
            r.region == HenckyReturn::cone ? 0. : 1.,
            0.,
            "a yes/no check");
    verdict("  sqrt(J2) / c - 1", root_j2(r.kirchhoff_stress) / c - 1., 1e-13, "rounding");
    verdict("  p / p_trial - 1 (no plastic volume change)",
            mean(r.kirchhoff_stress) / p_trial - 1.,
            1e-13,
            "rounding");
  }



  void
  apex_return()
  {
    std::printf("\n* (d) Apex return under tension (c cot phi = %.6f Pa)\n",
                c / std::tan(phi * M_PI / 180.));
    struct Case
    {
      const char  *name;
      Tensor<2, 3> f;
    };
    for (const double psi : {phi, 0.})
      for (const Case &apex_case :
           {Case{"1 % hydrostatic stretch", matrix({1.01, 0., 0., 0., 1.01, 0., 0., 0., 1.01})},
            Case{"1 % plane-strain stretch, 0.2 % shear",
                 matrix({1.01, 0.002, 0., 0., 1.01, 0., 0., 0., 1.})}})
        {
          const HenckyDruckerPrager model(E, nu, phi, c, psi);
          SymmetricTensor<2, 3>     b    = dealii::unit_symmetric_tensor<3>();
          const double              J    = dealii::determinant(apex_case.f);
          const HenckyStep          r    = step(model, b, apex_case.f, J);
          const double              apex = model.apex_mean_stress();
          std::printf("psi = %.0f, %s: region %s  p = %.6f  sqrt(J2) = %.3e  plastic volume "
                      "change = %.9f\n",
                      psi,
                      apex_case.name,
                      region_name(r.region),
                      mean(r.kirchhoff_stress),
                      root_j2(r.kirchhoff_stress),
                      dealii::trace(r.plastic_strain_increment));
          verdict("  region is not the apex (1) or is (0)",
                  r.region == HenckyReturn::apex ? 0. : 1.,
                  0.,
                  "a yes/no check");
          verdict("  p / (c cot phi) - 1",
                  mean(r.kirchhoff_stress) / apex - 1.,
                  1e-14,
                  "rounding of p rebuilt from principal values");
          verdict("  sqrt(J2) / p", root_j2(r.kirchhoff_stress) / apex, 1e-14, "rounding");
          verdict("  |sigma - (c cot phi / J) I| / |sigma|",
                  norm(r.cauchy_stress - apex / J * dealii::unit_symmetric_tensor<3>())
                    / norm(r.cauchy_stress),
                  1e-14,
                  "rounding");
          const double volume_trial = dealii::trace(
            HenckyDruckerPrager::logarithmic_strain(left_cauchy_green(apex_case.f)));
          verdict("  plastic volume change - (tr eps_trial - p_apex / K), relative",
                  dealii::trace(r.plastic_strain_increment)
                      / (volume_trial - apex / model.elasticity().bulk_modulus())
                    - 1.,
                  1e-13,
                  "log strains of 1e-2 subtracted");
        }
  }



  void
  path_independence()
  {
    std::printf(
      "\n* (e) Monotonic elastic path F(t) = I + t H, t = 0..1, 1000 steps against one\n");
    // c = 1 GPa: the path stays elastic, the yield check still runs at every step.
    const HenckyDruckerPrager model(E, nu, phi, 1e9, 10.);
    const Tensor<2, 3>        H = matrix({-0.15, 0.3, 0., 0.1, 0.1, 0., 0., 0., 0.});
    const Tensor<2, 3>        I = dealii::unit_symmetric_tensor<3>();
    const unsigned int        n = 1000;

    SymmetricTensor<2, 3> b_one = dealii::unit_symmetric_tensor<3>();
    const HenckyStep      one   = step(model, b_one, I + H, dealii::determinant(I + H));

    SymmetricTensor<2, 3> b_many = dealii::unit_symmetric_tensor<3>();
    HenckyStep            many;
    Tensor<2, 3>          previous    = I;
    bool                  all_elastic = true;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const Tensor<2, 3> F = I + (double(k) / n) * H;
        many        = step(model, b_many, F * dealii::invert(previous), dealii::determinant(F));
        all_elastic = all_elastic && many.region == HenckyReturn::elastic;
        previous    = F;
      }
    const SymmetricTensor<2, 3> exact = model.kirchhoff_stress(left_cauchy_green(I + H));
    print("tau, one step   ", one.kirchhoff_stress);
    print("tau, 1000 steps ", many.kirchhoff_stress);
    verdict("steps that yielded", all_elastic ? 0. : 1., 0., "a yes/no check");
    verdict("|tau(1000 steps) - tau(1 step)| / |tau|",
            norm(many.kirchhoff_stress - one.kirchhoff_stress) / norm(one.kirchhoff_stress),
            1e-11,
            "f b f^T and f = F_k F_k-1^-1 round b by ~1e-16 per step; 1000 steps, strains of "
            "~1e-1");
    verdict("|b^e(1000 steps) - F F^T| / |F F^T|",
            norm(b_many - left_cauchy_green(I + H)) / norm(left_cauchy_green(I + H)),
            1e-12,
            "~1e-16 per step, 1000 steps");
    verdict("|tau(1 step) - tau(F F^T)| / |tau|",
            norm(one.kirchhoff_stress - exact) / norm(exact),
            1e-14,
            "the same computation up to the symmetrization of f b f^T");

    // For contrast (printed, not checked): with c = 10 kPa the path yields, and plasticity
    // depends on the path.
    const HenckyDruckerPrager soft(E, nu, phi, c, 10.);
    SymmetricTensor<2, 3>     b_soft_one  = dealii::unit_symmetric_tensor<3>();
    SymmetricTensor<2, 3>     b_soft_many = dealii::unit_symmetric_tensor<3>();
    const HenckyStep          soft_one = step(soft, b_soft_one, I + H, dealii::determinant(I + H));
    HenckyStep                soft_many;
    previous = I;
    for (unsigned int k = 1; k <= n; ++k)
      {
        const Tensor<2, 3> F = I + (double(k) / n) * H;
        soft_many = step(soft, b_soft_many, F * dealii::invert(previous), dealii::determinant(F));
        previous  = F;
      }
    std::printf("(with c = 10 kPa the same path yields: one step and 1000 steps differ by "
                "%.3f of |tau|, as a plastic path should)\n",
                norm(soft_many.kirchhoff_stress - soft_one.kirchhoff_stress)
                  / norm(soft_one.kirchhoff_stress));
  }
} // namespace



int
main()
{
  small_strains();
  rigid_rotation();
  plastic_loading();
  cylinder_return();
  apex_return();
  path_independence();
  return unit_check::finish();
}
