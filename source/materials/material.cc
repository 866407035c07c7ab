#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/material.h>

namespace slidewave
{
  namespace materials
  {
    void
    MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Name",
                        "",
                        Anything(),
                        "The name of the material; geometry regions refer to it "
                        "by this name.");
      prm.declare_entry("Model",
                        "drucker prager",
                        Selection("linear elastic|drucker prager|hencky drucker prager"),
                        "'linear elastic': Hooke's law only. 'drucker prager': "
                        "linear elasticity with the non-associative "
                        "Drucker-Prager criterion matched to Mohr-Coulomb in "
                        "plane strain and a tension cutoff (paper 000, Eqs. 2-4); "
                        "both small strain, on the Jaumann rate of the stress. "
                        "'hencky drucker prager': finite strain (paper 002, "
                        "Sec. 2.2): Hencky hyperelasticity on the elastic left "
                        "Cauchy-Green tensor b^e of F = F^e F^p (carried by the "
                        "points), the same cone and flow rule, returned in "
                        "principal logarithmic strains; no tension cutoff (the "
                        "apex c cot(phi) bounds the mean stress).");
      prm.declare_entry("Density",
                        "2000",
                        Double(),
                        "Mass density rho [kg/m^3] (of the saturated soil in a "
                        "total stress analysis).");
      prm.declare_entry("Young's modulus",
                        "1e7",
                        Double(),
                        "Young's modulus E [Pa] of the linear elasticity.");
      prm.declare_entry("Poisson ratio",
                        "0.3",
                        Double(),
                        "Poisson ratio nu [-] of the linear elasticity, in "
                        "(-1, 0.5) so that the bulk and shear moduli are "
                        "positive; values close to 0.5 (nearly incompressible) "
                        "make the time step small.");
      prm.declare_entry("Friction angle",
                        "30",
                        Double(),
                        "Friction angle phi [degrees] of the Drucker-Prager "
                        "criterion, in [0, 90). 0 gives the undrained (von "
                        "Mises) criterion sqrt(J2) = c of a total stress "
                        "analysis, where the cohesion is the undrained shear "
                        "strength s_u.");
      prm.declare_entry("Cohesion",
                        "0",
                        Double(),
                        "Cohesion c [Pa] of the Drucker-Prager criterion, >= 0.");
      prm.declare_entry("Dilatancy angle",
                        "0",
                        Double(),
                        "Dilatancy angle psi [degrees] of the plastic potential, "
                        "at most the friction angle: 0 gives plastic flow without "
                        "volume change, the friction angle gives associated "
                        "flow. 'drucker prager' also takes a negative angle down to "
                        "minus the friction angle (compaction under shear: a loose "
                        "soil), as long as G + 9 K alpha_phi alpha_psi > 0.1 G, and so "
                        "does 'hencky drucker prager'.");
      prm.declare_entry("Dilatancy law",
                        "constant",
                        Selection("constant|critical state"),
                        "'constant': the 'Dilatancy angle'. 'critical state' ('drucker "
                        "prager' or 'hencky drucker prager' in 'Physics = granular water', "
                        "where each point knows its porosity n): tan psi = K (n_c - n) with the "
                        "'Critical porosity' n_c "
                        "and the 'Dilatancy factor' K (Pailha and Pouliquen 2009, in the "
                        "solid fraction 1 - n): a packing denser than the critical one "
                        "dilates under shear, a looser one compacts, and both approach n_c; "
                        "psi is kept within [-phi, phi] and where the return is well posed "
                        "('Dilatancy angle' stays 0).");
      prm.declare_entry("Critical porosity",
                        "0.42",
                        Double(),
                        "Porosity n_c of the critical state, where shear goes on at constant "
                        "volume, in (0, 0.99) ('Dilatancy law = critical state'; 0.42 is a "
                        "solid fraction of 0.58, glass beads).");
      prm.declare_entry("Dilatancy factor",
                        "4.09",
                        Double(),
                        "K in tan psi = K (n_c - n), >= 0 ('Dilatancy law = critical "
                        "state'; 4.09 for glass beads, Pailha and Pouliquen 2009).");
      prm.declare_entry(
        "Friction law",
        "constant",
        Selection("constant|inertial|viscous"),
        "'constant': the 'Friction angle' at every rate (rate-independent "
        "plasticity, whose flowing states have no length scale). 'inertial' (mu(I), "
        "dry grains, Jop, Forterre and Pouliquen 2006) and 'viscous' (mu(J), "
        "grains in a liquid, Boyer, Guazzelli and Pouliquen 2011): tan phi = "
        "mu_s + (mu_2 - mu_s) / (1 + X_0 / X) (that is, X / (X + X_0), finite as X grows without "
        "bound) with mu_s = tan('Friction angle'), "
        "mu_2 = tan('Friction angle at high rate'), X the inertial number "
        "I = gamma_dot d sqrt(rho_s / p') or the viscous number J = eta_f "
        "gamma_dot / p' of the point's shear rate gamma_dot and mean effective "
        "pressure p', X_0 its reference value; mu_s where p' <= 0. The cohesion "
        "term stays the static one. 'drucker prager' with a 'Friction angle' "
        "above 0 only.");
      prm.declare_entry("Friction angle at high rate",
                        "40",
                        Double(),
                        "phi_2 [degrees], the friction angle as the rate number goes to "
                        "infinity ('Friction law' inertial or viscous), in ['Friction angle', "
                        "90). Glass beads: 32.8 (Jop et al. 2006).");
      prm.declare_entry("Reference inertial number",
                        "0.279",
                        Double(),
                        "I_0 ('Friction law = inertial'), > 0: the inertial number at which "
                        "tan phi is halfway between mu_s and mu_2 (0.279: glass beads, Jop et "
                        "al. 2006).");
      prm.declare_entry("Reference viscous number",
                        "0.005",
                        Double(),
                        "J_0 ('Friction law = viscous'), > 0: the viscous number at which tan "
                        "phi is halfway between mu_s and mu_2 (0.005: Boyer et al. 2011).");
      prm.declare_entry("Grain diameter",
                        "0.5e-3",
                        Double(),
                        "d [m] of the inertial number ('Friction law = inertial'), > 0.");
      prm.declare_entry("Grain density",
                        "2500",
                        Double(),
                        "rho_s [kg/m^3] of the inertial number ('Friction law = inertial'), "
                        "> 0: the grains' own density, not the bulk 'Density'.");
      prm.declare_entry("Fluid viscosity",
                        "1e-3",
                        Double(),
                        "eta_f [Pa s] of the viscous number ('Friction law = viscous'), > 0: "
                        "the pore liquid's viscosity.");
      prm.declare_entry("Tension cutoff",
                        "0",
                        Double(),
                        "Tensile strength T [Pa] on the mean stress p = tr(sigma)/3 "
                        "(tension positive), >= 0: the Drucker-Prager model keeps "
                        "p <= T. With a friction angle above 0, values above "
                        "c cot(phi), the apex of the cone, have no effect.");
    }



    void
    MaterialParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      this->path                   = path;
      name                         = dealii::Utilities::trim(prm.get("Name"));
      const std::string model_name = prm.get("Model");
      model                     = model_name == "linear elastic" ? MaterialModel::linear_elastic :
                                  model_name == "hencky drucker prager" ? MaterialModel::hencky_drucker_prager :
                                                                          MaterialModel::drucker_prager;
      density                   = prm.get_double("Density");
      youngs_modulus            = prm.get_double("Young's modulus");
      poisson_ratio             = prm.get_double("Poisson ratio");
      friction_angle            = prm.get_double("Friction angle");
      cohesion                  = prm.get_double("Cohesion");
      dilatancy_angle           = prm.get_double("Dilatancy angle");
      tension_cutoff            = prm.get_double("Tension cutoff");
      critical_state_dilatancy  = prm.get("Dilatancy law") == "critical state";
      critical_porosity         = prm.get_double("Critical porosity");
      dilatancy_factor          = prm.get_double("Dilatancy factor");
      const std::string law     = prm.get("Friction law");
      friction_law              = law == "inertial" ? FrictionLaw::inertial :
                                  law == "viscous"  ? FrictionLaw::viscous :
                                                      FrictionLaw::constant;
      high_rate_friction_angle  = prm.get_double("Friction angle at high rate");
      reference_inertial_number = prm.get_double("Reference inertial number");
      reference_viscous_number  = prm.get_double("Reference viscous number");
      grain_diameter            = prm.get_double("Grain diameter");
      grain_density             = prm.get_double("Grain density");
      fluid_viscosity           = prm.get_double("Fluid viscosity");

      if (name.empty())
        throw InputError(path + "/Name",
                         prm.get("Name"),
                         "a non-empty name, by which geometry regions refer to "
                         "the material");
      require_positive(path + "/Density", density);
      require_positive(path + "/Young's modulus", youngs_modulus);
      if (!(poisson_ratio > -1. && poisson_ratio < 0.5))
        throw InputError(path + "/Poisson ratio",
                         to_string(poisson_ratio),
                         "a number in (-1, 0.5), where the bulk and shear moduli "
                         "are positive and finite");
      require_in_range(path + "/Friction angle", friction_angle, 0., true, 90., false);
      // Both Drucker-Prager models take a negative dilatancy (compaction under shear, a
      // loose soil) as long as their return stays well posed: G + 9 K alpha_phi alpha_psi > 0
      // (DruckerPrager::return_to_yield_surface and HenckyDruckerPrager::update divide by
      // it).
      // With a friction that rises with the rate, up to phi_2: the return's bound holds at
      // the largest friction.
      const bool rate_law = friction_law != FrictionLaw::constant;
      if (rate_law)
        {
          if (model != MaterialModel::drucker_prager)
            throw InputError(path + "/Friction law",
                             law,
                             "constant with 'Model = " + prm.get("Model")
                               + "' (a rate-dependent friction is a law of 'drucker prager')");
          if (!(friction_angle > 0.))
            throw InputError(path + "/Friction angle",
                             prm.get("Friction angle"),
                             "a number in (0, 90) with 'Friction law = " + law
                               + "' (a friction that rises with the rate needs one at rest; "
                                 "0 is the undrained clay's cylinder)");
          require_in_range(path + "/Friction angle at high rate",
                           high_rate_friction_angle,
                           friction_angle,
                           true,
                           90.,
                           false);
          if (friction_law == FrictionLaw::inertial)
            {
              require_positive(path + "/Reference inertial number", reference_inertial_number);
              require_positive(path + "/Grain diameter", grain_diameter);
              require_positive(path + "/Grain density", grain_density);
            }
          else
            {
              require_positive(path + "/Reference viscous number", reference_viscous_number);
              require_positive(path + "/Fluid viscosity", fluid_viscosity);
            }
        }
      const double largest_friction = rate_law ? high_rate_friction_angle : friction_angle;
      const bool   plastic          = model != MaterialModel::linear_elastic;
      const double lowest           = plastic ? -friction_angle : 0.;
      const double K                = youngs_modulus / (3. * (1. - 2. * poisson_ratio));
      const double G                = youngs_modulus / (2. * (1. + poisson_ratio));
      const bool   well_posed
        = G
            + 9. * K * DruckerPrager::plane_strain_coefficient(largest_friction)
                * DruckerPrager::plane_strain_coefficient(std::min(dilatancy_angle, 0.))
          > 0.1 * G;
      if (!(dilatancy_angle >= lowest && dilatancy_angle <= friction_angle) || !well_posed)
        throw InputError(path + "/Dilatancy angle",
                         to_string(dilatancy_angle),
                         plastic ?
                           "a number in [-" + to_string(friction_angle) + ", "
                             + to_string(friction_angle)
                             + "] (at most the friction angle; negative: compaction under "
                               "shear) with G + 9 K alpha_phi alpha_psi > 0.1 G"
                             + std::string(rate_law ? " (alpha_phi of the 'Friction angle at "
                                                      "high rate')" :
                                                      "") :
                           "a number in [0, " + to_string(friction_angle)
                             + "]: the dilatancy angle may not exceed the friction angle");
      if (critical_state_dilatancy)
        {
          if (!plastic)
            throw InputError(path + "/Dilatancy law",
                             "critical state",
                             "constant with 'Model = " + prm.get("Model")
                               + "' (a state-dependent dilatancy needs a plastic model: "
                                 "'drucker prager' or 'hencky drucker prager')");
          if (dilatancy_angle != 0.)
            throw InputError(path + "/Dilatancy angle",
                             prm.get("Dilatancy angle"),
                             "0 (the default) with 'Dilatancy law = critical state', which "
                             "sets the angle from each point's porosity");
          require_in_range(path + "/Critical porosity", critical_porosity, 0., false, 0.99, false);
          require_non_negative(path + "/Dilatancy factor", dilatancy_factor);
        }
      require_non_negative(path + "/Cohesion", cohesion);
      require_non_negative(path + "/Tension cutoff", tension_cutoff);
      if (model == MaterialModel::hencky_drucker_prager && tension_cutoff != 0.)
        throw InputError(path + "/Tension cutoff",
                         prm.get("Tension cutoff"),
                         "0 with 'Model = hencky drucker prager', which has no tension "
                         "cutoff: the apex of its cone, c cot(phi), bounds the mean stress");
    }



    std::string
    MaterialParameters::signature() const
    {
      return "'" + name + "'"
             + (model == MaterialModel::hencky_drucker_prager ? " (finite strain)" : "");
    }



    void
    apply_jaumann_rotation(dealii::SymmetricTensor<2, 3> &stress, const double spin_increment_xy)
    {
      // σ + Wσ - σW for W_xy = ω, W_yx = -ω (see the documentation in the
      // header); computed from the old components.
      const double omega = spin_increment_xy;
      const double xx    = stress[0][0];
      const double yy    = stress[1][1];
      const double xy    = stress[0][1];
      const double xz    = stress[0][2];
      const double yz    = stress[1][2];
      stress[0][0] += 2. * omega * xy;
      stress[1][1] -= 2. * omega * xy;
      stress[0][1] += omega * (yy - xx);
      stress[0][2] += omega * yz;
      stress[1][2] -= omega * xz;
    }



    Material::Material(const MaterialParameters &parameters)
      : parameters(parameters)
      , elastic(parameters.youngs_modulus, parameters.poisson_ratio)
      , static_friction(std::tan(parameters.friction_angle * M_PI / 180.))
      , high_rate_friction(std::tan(parameters.high_rate_friction_angle * M_PI / 180.))
    {
      if (parameters.model == MaterialModel::drucker_prager)
        plasticity.emplace(parameters.youngs_modulus,
                           parameters.poisson_ratio,
                           parameters.friction_angle,
                           parameters.cohesion,
                           parameters.dilatancy_angle,
                           parameters.tension_cutoff);
      if (parameters.model != MaterialModel::linear_elastic)
        {
          // A state-dependent alpha_psi stays within [-alpha_phi, alpha_phi] and keeps
          // G + 9 K alpha_phi alpha_psi >= 0.1 G (MaterialParameters::parse_parameters);
          // the Hencky model's cone is the small-strain one's (HenckyDruckerPrager).
          // With a rate-dependent friction the bound holds at its largest, phi_2.
          const double alpha_phi
            = DruckerPrager::plane_strain_coefficient(parameters.friction_angle);
          const double largest_alpha_phi
            = rate_dependent_friction() ?
                DruckerPrager::plane_strain_coefficient(parameters.high_rate_friction_angle) :
                alpha_phi;
          highest_alpha_psi = alpha_phi;
          lowest_alpha_psi  = -alpha_phi;
          if (largest_alpha_phi > 0.)
            lowest_alpha_psi = std::max(lowest_alpha_psi,
                                        -0.9 * elastic.shear_modulus()
                                          / (9. * elastic.bulk_modulus() * largest_alpha_phi));
        }
    }



    double
    Material::dilatancy_coefficient(const double porosity) const
    {
      const double t = parameters.dilatancy_factor * (parameters.critical_porosity - porosity);
      return std::clamp(t / std::sqrt(9. + 12. * t * t), lowest_alpha_psi, highest_alpha_psi);
    }



    double
    Material::friction_tangent(const double shear_rate, const double pressure) const
    {
      // No rate, or no pressure to carry a friction (at or beyond the apex, where the
      // cohesion alone holds): the friction at rest.
      if (!(shear_rate > 0.) || !(pressure > 0.))
        return static_friction;
      const bool   inertial = parameters.friction_law == FrictionLaw::inertial;
      const double number   = inertial ? shear_rate * parameters.grain_diameter
                                         * std::sqrt(parameters.grain_density / pressure) :
                                         parameters.fluid_viscosity * shear_rate / pressure;
      const double reference
        = inertial ? parameters.reference_inertial_number : parameters.reference_viscous_number;
      // X_0 / X: zero for an infinite X (a vanishing pressure), so the law stays finite.
      return static_friction + (high_rate_friction - static_friction) / (1. + reference / number);
    }



    void
    Material::update_stress_at_rate(dealii::SymmetricTensor<2, 3>       &stress,
                                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                                    const double                         spin_increment_xy,
                                    double                              &equivalent_plastic_strain,
                                    const double                         alpha_psi,
                                    const double                         dt) const
    {
      Assert(parameters.model == MaterialModel::drucker_prager, dealii::ExcInternalError());
      Assert(dt > 0., dealii::ExcMessage("a rate-dependent friction needs a positive step"));
      apply_jaumann_rotation(stress, spin_increment_xy);
      // The trial stress's pressure: its trace needs only the bulk modulus (the return
      // builds the trial stress itself).
      const double pressure
        = -dealii::trace(stress) / 3. - elastic.bulk_modulus() * dealii::trace(strain_increment);
      const dealii::SymmetricTensor<2, 3> e          = dealii::deviator(strain_increment);
      const double                        shear_rate = std::sqrt(2. * (e * e)) / dt;
      // The rate raises the friction only; the cohesion term stays the static one, so that
      // the strength at zero pressure (and the apex's tension) does not fall with the rate.
      const Cone cone{
        DruckerPrager::cone_of_tangent(friction_tangent(shear_rate, pressure), 0.).alpha_phi,
        plasticity->k_c()};
      plasticity->update_stress(stress,
                                strain_increment,
                                equivalent_plastic_strain,
                                cone,
                                std::isnan(alpha_psi) ? plasticity->alpha_psi() : alpha_psi);
    }



    void
    Material::update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                            const dealii::SymmetricTensor<2, 3> &strain_increment,
                            const double                         spin_increment_xy,
                            double                              &equivalent_plastic_strain,
                            const double                         alpha_psi) const
    {
      Assert(parameters.model == MaterialModel::drucker_prager, dealii::ExcInternalError());
      apply_jaumann_rotation(stress, spin_increment_xy);
      plasticity->update_stress(stress, strain_increment, equivalent_plastic_strain, alpha_psi);
    }



    void
    Material::update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                            const dealii::SymmetricTensor<2, 3> &strain_increment,
                            const double                         spin_increment_xy,
                            double                              &equivalent_plastic_strain) const
    {
      apply_jaumann_rotation(stress, spin_increment_xy);
      switch (parameters.model)
        {
          case MaterialModel::linear_elastic:
            stress += elastic.stress_increment(strain_increment);
            break;
          case MaterialModel::drucker_prager:
            plasticity->update_stress(stress, strain_increment, equivalent_plastic_strain);
            break;
          case MaterialModel::hencky_drucker_prager:
            Assert(false,
                   dealii::ExcMessage("a Hencky material's points are updated from their "
                                      "deformation (soil::FiniteStrainPoints)"));
            break;
        }
    }



    double
    Material::p_wave_modulus() const
    {
      return elastic.p_wave_modulus();
    }



    double
    Material::density() const
    {
      return parameters.density;
    }



    const std::string &
    Material::name() const
    {
      return parameters.name;
    }



    MaterialModel
    Material::model() const
    {
      return parameters.model;
    }



    const LinearElastic &
    Material::elasticity() const
    {
      return elastic;
    }
  } // namespace materials
} // namespace slidewave
