#include <algorithm>
#include <cmath>
#include <limits>
#include <slidewave/materials/drucker_prager.h>

namespace slidewave
{
  namespace materials
  {
    namespace
    {
      /** Rounding tolerance, relative to the stresses being compared. */
      constexpr double relative_tolerance = 1e-12;

      double
      tangent_of_degrees(const double angle_degrees)
      {
        return std::tan(angle_degrees * M_PI / 180.);
      }

      /** sqrt(J2) of a deviator @p s, J2 = s:s/2. */
      double
      root_j2(const dealii::SymmetricTensor<2, 3> &s)
      {
        return std::sqrt(0.5 * (s * s));
      }
    } // namespace



    DruckerPrager::DruckerPrager(const double youngs_modulus,
                                 const double poisson_ratio,
                                 const double friction_angle_degrees,
                                 const double cohesion,
                                 const double dilatancy_angle_degrees,
                                 const double tension_cutoff)
      : elastic(youngs_modulus, poisson_ratio)
      , friction_coefficient(plane_strain_coefficient(friction_angle_degrees))
      , dilatancy_coefficient(plane_strain_coefficient(dilatancy_angle_degrees))
      , cohesion_term(
          3. * cohesion
          / std::sqrt(9. + 12. * std::pow(tangent_of_degrees(friction_angle_degrees), 2)))
      , cutoff(tension_cutoff)
    {
    }



    double
    DruckerPrager::plane_strain_coefficient(const double angle_degrees)
    {
      const double t = tangent_of_degrees(angle_degrees);
      return t / std::sqrt(9. + 12. * t * t);
    }



    PlasticCorrection
    DruckerPrager::update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                                 const dealii::SymmetricTensor<2, 3> &strain_increment,
                                 double &equivalent_plastic_strain) const
    {
      return update_stress(stress,
                           strain_increment,
                           equivalent_plastic_strain,
                           dilatancy_coefficient);
    }



    PlasticCorrection
    DruckerPrager::update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                                 const dealii::SymmetricTensor<2, 3> &strain_increment,
                                 double                              &equivalent_plastic_strain,
                                 const double                         alpha_psi) const
    {
      return update_stress(stress, strain_increment, equivalent_plastic_strain, cone(), alpha_psi);
    }



    PlasticCorrection
    DruckerPrager::update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                                 const dealii::SymmetricTensor<2, 3> &strain_increment,
                                 double                              &equivalent_plastic_strain,
                                 const Cone                          &cone,
                                 const double                         alpha_psi) const
    {
      stress += elastic.stress_increment(strain_increment);
      const PlasticCorrection correction = return_to_yield_surface(stress, cone, alpha_psi);
      equivalent_plastic_strain += correction.equivalent_plastic_strain_increment;
      return correction;
    }



    Cone
    DruckerPrager::cone() const
    {
      return {friction_coefficient, cohesion_term};
    }



    Cone
    DruckerPrager::cone_of_tangent(const double tangent, const double cohesion)
    {
      const double root = std::sqrt(9. + 12. * tangent * tangent);
      return {tangent / root, 3. * cohesion / root};
    }



    PlasticCorrection
    DruckerPrager::return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress) const
    {
      return return_to_yield_surface(stress, dilatancy_coefficient);
    }



    PlasticCorrection
    DruckerPrager::return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress,
                                           const double                   alpha_psi) const
    {
      return return_to_yield_surface(stress, cone(), alpha_psi);
    }



    PlasticCorrection
    DruckerPrager::return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress,
                                           const Cone                    &cone,
                                           const double                   alpha_psi) const
    {
      const double a_phi  = cone.alpha_phi;
      const double k_cone = cone.k_c;
      const double K      = elastic.bulk_modulus();
      const double G      = elastic.shear_modulus();

      const dealii::SymmetricTensor<2, 3> trial   = stress;
      const double                        p_trial = dealii::trace(trial) / 3.;
      const dealii::SymmetricTensor<2, 3> s_trial = dealii::deviator(trial);
      const double                        q_trial = root_j2(s_trial);
      const double                        f_trial = 3. * a_phi * p_trial + q_trial - k_cone;

      const double cone_scale   = k_cone + std::abs(3. * a_phi * p_trial) + q_trial;
      const bool   outside_cone = f_trial > relative_tolerance * cone_scale;
      const bool   beyond_cutoff
        = p_trial > cutoff + relative_tolerance * (cutoff + std::abs(p_trial) + q_trial);

      PlasticCorrection correction;
      if (!outside_cone && !beyond_cutoff)
        return correction;

      // The corrected state, described by its mean stress and sqrt(J2); the
      // deviator keeps the direction of the trial deviator in every region.
      double p     = p_trial;
      double q     = q_trial;
      bool   found = false;

      if (outside_cone)
        {
          const double dlambda = f_trial / (G + 9. * K * a_phi * alpha_psi);
          const double q_cone  = q_trial - G * dlambda;
          const double p_cone  = p_trial - 3. * K * alpha_psi * dlambda;
          // Without friction the cone is a cylinder: q_cone = k_c >= 0 up to
          // rounding, and there is no apex to fall back on.
          const bool has_apex = a_phi > 0.;
          if ((q_cone >= 0. || !has_apex) && p_cone <= cutoff)
            {
              correction.region = ReturnRegion::cone;
              p                 = p_cone;
              q                 = std::max(q_cone, 0.);
              found             = true;
            }
        }

      if (!found && p_trial > cutoff)
        {
          const double f_at_cutoff = 3. * a_phi * cutoff + q_trial - k_cone;
          if (f_at_cutoff <= relative_tolerance * cone_scale)
            {
              correction.region = ReturnRegion::tension_cutoff;
              p                 = cutoff;
              found             = true;
            }
        }

      if (!found)
        {
          correction.region = ReturnRegion::corner;
          p                 = std::min(cutoff,
                       a_phi > 0. ? k_cone / (3. * a_phi) :
                                                    std::numeric_limits<double>::infinity());
          q                 = std::min(q_trial, std::max(k_cone - 3. * a_phi * p, 0.));
        }

      stress = p * dealii::unit_symmetric_tensor<3>();
      if (q_trial > 0.)
        stress += (q / q_trial) * s_trial;

      correction.plastic_strain_increment = elastic.strain_increment(trial - stress);
      correction.equivalent_plastic_strain_increment
        = equivalent_plastic_strain(correction.plastic_strain_increment);
      return correction;
    }



    double
    DruckerPrager::yield_function(const dealii::SymmetricTensor<2, 3> &stress) const
    {
      return friction_coefficient * dealii::trace(stress) + root_j2(dealii::deviator(stress))
             - cohesion_term;
    }



    double
    DruckerPrager::alpha_phi() const
    {
      return friction_coefficient;
    }



    double
    DruckerPrager::alpha_psi() const
    {
      return dilatancy_coefficient;
    }



    double
    DruckerPrager::k_c() const
    {
      return cohesion_term;
    }



    double
    DruckerPrager::apex_mean_stress() const
    {
      if (friction_coefficient > 0.)
        return cohesion_term / (3. * friction_coefficient);
      return std::numeric_limits<double>::infinity();
    }



    double
    DruckerPrager::tension_cutoff() const
    {
      return cutoff;
    }



    const LinearElastic &
    DruckerPrager::elasticity() const
    {
      return elastic;
    }



    double
    DruckerPrager::equivalent_plastic_strain(const dealii::SymmetricTensor<2, 3> &strain)
    {
      const dealii::SymmetricTensor<2, 3> e = dealii::deviator(strain);
      return std::sqrt(2. / 3. * (e * e));
    }
  } // namespace materials
} // namespace slidewave
