#include <array>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <limits>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/hencky_drucker_prager.h>

namespace slidewave
{
  namespace materials
  {
    namespace
    {
      /** Rounding tolerance of the yield check, relative to the stresses compared. */
      constexpr double relative_tolerance = 1e-12;

      using Principal = std::array<double, 3>;

      /** Eigenvalues and eigenvectors of a positive definite @p b, descending. */
      std::array<std::pair<double, dealii::Tensor<1, 3>>, 3>
      spectral_decomposition(const dealii::SymmetricTensor<2, 3> &b)
      {
        const auto pairs
          = dealii::eigenvectors(b, dealii::SymmetricTensorEigenvectorMethod::jacobi);
        for (const auto &pair : pairs)
          AssertThrow(pair.first > 0. && std::isfinite(pair.first),
                      dealii::ExcMessage("The elastic left Cauchy-Green tensor is not positive "
                                         "definite (an eigenvalue is "
                                         + std::to_string(pair.first) + ")."));
        return pairs;
      }

      /** Σ_A values_A n_A ⊗ n_A. */
      dealii::SymmetricTensor<2, 3>
      from_principal(const Principal                                              &values,
                     const std::array<std::pair<double, dealii::Tensor<1, 3>>, 3> &axes)
      {
        dealii::SymmetricTensor<2, 3> t;
        for (unsigned int a = 0; a < 3; ++a)
          t += values[a]
               * dealii::symmetrize(dealii::outer_product(axes[a].second, axes[a].second));
        return t;
      }

      double
      sum(const Principal &v)
      {
        return v[0] + v[1] + v[2];
      }
    } // namespace



    HenckyDruckerPrager::HenckyDruckerPrager(const double youngs_modulus,
                                             const double poisson_ratio,
                                             const double friction_angle_degrees,
                                             const double cohesion,
                                             const double dilatancy_angle_degrees)
      // The cone of the small-strain model itself (its plane-strain fit to Mohr-Coulomb,
      // k_c = 3 c / sqrt(9 + 12 tan^2 phi)), so that the two cannot drift apart; no
      // tension cutoff (paper 002 has none).
      : cone(youngs_modulus,
             poisson_ratio,
             friction_angle_degrees,
             cohesion,
             dilatancy_angle_degrees,
             0.)
    {
    }



    HenckyStep
    HenckyDruckerPrager::update(dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green,
                                const dealii::Tensor<2, 3>    &deformation_gradient_increment,
                                const double                   jacobian,
                                double                        &equivalent_plastic_strain) const
    {
      return update(elastic_left_cauchy_green,
                    deformation_gradient_increment,
                    jacobian,
                    equivalent_plastic_strain,
                    cone.alpha_psi());
    }



    HenckyStep
    HenckyDruckerPrager::update(dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green,
                                const dealii::Tensor<2, 3>    &deformation_gradient_increment,
                                const double                   jacobian,
                                double                        &equivalent_plastic_strain,
                                const double                   alpha_psi) const
    {
      const dealii::Tensor<2, 3> &f = deformation_gradient_increment;
      AssertThrow(dealii::determinant(f) > 0.,
                  dealii::ExcMessage("The incremental deformation gradient must have a positive "
                                     "determinant (it is "
                                     + std::to_string(dealii::determinant(f)) + ")."));
      AssertThrow(jacobian > 0.,
                  dealii::ExcMessage("The Jacobian J = det F must be positive (it is "
                                     + std::to_string(jacobian) + ")."));

      // Elastic trial state (Eq. 15 with F^p frozen), symmetrized against rounding.
      const dealii::SymmetricTensor<2, 3> b_trial = dealii::symmetrize(
        f * static_cast<dealii::Tensor<2, 3>>(elastic_left_cauchy_green) * dealii::transpose(f));
      const auto axes = spectral_decomposition(b_trial);

      const double K                     = cone.elasticity().bulk_modulus();
      const double G                     = cone.elasticity().shear_modulus();
      const double friction_coefficient  = cone.alpha_phi();
      const double dilatancy_coefficient = alpha_psi;
      const double cohesion_term         = cone.k_c();

      // Principal logarithmic strains and the Hencky stress (Eq. 16).
      Principal eps_trial;
      for (unsigned int a = 0; a < 3; ++a)
        eps_trial[a] = 0.5 * std::log(axes[a].first);
      const double volumetric_trial = sum(eps_trial);
      const double p_trial          = K * volumetric_trial;
      Principal    s_trial;
      for (unsigned int a = 0; a < 3; ++a)
        s_trial[a] = 2. * G * (eps_trial[a] - volumetric_trial / 3.);
      const double q_trial = std::sqrt(
        0.5 * (s_trial[0] * s_trial[0] + s_trial[1] * s_trial[1] + s_trial[2] * s_trial[2]));

      // Yield check (Eq. 17).
      const double f_trial = 3. * friction_coefficient * p_trial + q_trial - cohesion_term;
      const double yield_scale
        = cohesion_term + std::abs(3. * friction_coefficient * p_trial) + q_trial;

      HenckyStep step;
      double     p = p_trial;
      double     q = q_trial;
      if (f_trial > relative_tolerance * yield_scale)
        {
          const double dgamma
            = f_trial / (G + 9. * K * friction_coefficient * dilatancy_coefficient);
          const double q_cone = q_trial - G * dgamma;
          if (q_cone >= 0. || friction_coefficient == 0.)
            {
              step.region = HenckyReturn::cone;
              p           = p_trial - 3. * K * dilatancy_coefficient * dgamma;
              q           = std::max(q_cone, 0.);
            }
          else
            {
              step.region = HenckyReturn::apex;
              p           = apex_mean_stress();
              q           = 0.;
            }
        }

      // Returned principal stresses along the trial axes, and the elastic strains they need.
      const double deviator_scale = q_trial > 0. ? q / q_trial : 0.;
      Principal    tau;
      Principal    eps;
      Principal    plastic;
      for (unsigned int a = 0; a < 3; ++a)
        {
          tau[a]     = p + deviator_scale * s_trial[a];
          eps[a]     = p / (3. * K) + deviator_scale * s_trial[a] / (2. * G);
          plastic[a] = eps_trial[a] - eps[a];
        }

      if (step.region == HenckyReturn::elastic)
        {
          elastic_left_cauchy_green = b_trial;
          plastic                   = {{0., 0., 0.}};
        }
      else
        {
          Principal stretches_squared;
          for (unsigned int a = 0; a < 3; ++a)
            stretches_squared[a] = std::exp(2. * eps[a]);
          elastic_left_cauchy_green = from_principal(stretches_squared, axes);
        }

      step.kirchhoff_stress         = from_principal(tau, axes);
      step.cauchy_stress            = step.kirchhoff_stress / jacobian;
      step.plastic_strain_increment = from_principal(plastic, axes);
      step.equivalent_plastic_strain_increment
        = DruckerPrager::equivalent_plastic_strain(step.plastic_strain_increment);
      equivalent_plastic_strain += step.equivalent_plastic_strain_increment;
      return step;
    }



    dealii::SymmetricTensor<2, 3>
    HenckyDruckerPrager::kirchhoff_stress(
      const dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green) const
    {
      const dealii::SymmetricTensor<2, 3> eps = logarithmic_strain(elastic_left_cauchy_green);
      return cone.elasticity().stress_increment(eps);
    }



    dealii::SymmetricTensor<2, 3>
    HenckyDruckerPrager::elastic_left_cauchy_green(
      const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const
    {
      // The principal axes of tau are those of epsilon (isotropic elasticity); no positivity
      // needed, so the eigenvectors of tau itself.
      const auto axes
        = dealii::eigenvectors(kirchhoff_stress, dealii::SymmetricTensorEigenvectorMethod::jacobi);
      const double K = cone.elasticity().bulk_modulus();
      const double G = cone.elasticity().shear_modulus();
      const double p = (axes[0].first + axes[1].first + axes[2].first) / 3.;
      Principal    stretches_squared;
      for (unsigned int a = 0; a < 3; ++a)
        stretches_squared[a] = std::exp(2. * (p / (3. * K) + (axes[a].first - p) / (2. * G)));
      return from_principal(stretches_squared, axes);
    }



    double
    HenckyDruckerPrager::yield_function(const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const
    {
      const dealii::SymmetricTensor<2, 3> s = dealii::deviator(kirchhoff_stress);
      return cone.alpha_phi() * dealii::trace(kirchhoff_stress) + std::sqrt(0.5 * (s * s))
             - cone.k_c();
    }



    dealii::SymmetricTensor<2, 3>
    HenckyDruckerPrager::logarithmic_strain(const dealii::SymmetricTensor<2, 3> &left_cauchy_green)
    {
      const auto axes = spectral_decomposition(left_cauchy_green);
      Principal  eps;
      for (unsigned int a = 0; a < 3; ++a)
        eps[a] = 0.5 * std::log(axes[a].first);
      return from_principal(eps, axes);
    }



  } // namespace materials
} // namespace slidewave
