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
      model                    = model_name == "linear elastic" ? MaterialModel::linear_elastic :
                                 model_name == "hencky drucker prager" ? MaterialModel::hencky_drucker_prager :
                                                                         MaterialModel::drucker_prager;
      density                  = prm.get_double("Density");
      youngs_modulus           = prm.get_double("Young's modulus");
      poisson_ratio            = prm.get_double("Poisson ratio");
      friction_angle           = prm.get_double("Friction angle");
      cohesion                 = prm.get_double("Cohesion");
      dilatancy_angle          = prm.get_double("Dilatancy angle");
      tension_cutoff           = prm.get_double("Tension cutoff");
      critical_state_dilatancy = prm.get("Dilatancy law") == "critical state";
      critical_porosity        = prm.get_double("Critical porosity");
      dilatancy_factor         = prm.get_double("Dilatancy factor");

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
      const bool   plastic    = model != MaterialModel::linear_elastic;
      const double lowest     = plastic ? -friction_angle : 0.;
      const double K          = youngs_modulus / (3. * (1. - 2. * poisson_ratio));
      const double G          = youngs_modulus / (2. * (1. + poisson_ratio));
      const bool   well_posed = G
                                + 9. * K * DruckerPrager::plane_strain_coefficient(friction_angle)
                                    * DruckerPrager::plane_strain_coefficient(dilatancy_angle)
                              > 0.1 * G;
      if (!(dilatancy_angle >= lowest && dilatancy_angle <= friction_angle) || !well_posed)
        throw InputError(path + "/Dilatancy angle",
                         to_string(dilatancy_angle),
                         plastic ? "a number in [-" + to_string(friction_angle) + ", "
                                     + to_string(friction_angle)
                                     + "] (at most the friction angle; negative: compaction under "
                                       "shear) with G + 9 K alpha_phi alpha_psi > 0.1 G" :
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
          const double alpha_phi
            = DruckerPrager::plane_strain_coefficient(parameters.friction_angle);
          highest_alpha_psi = alpha_phi;
          lowest_alpha_psi  = -alpha_phi;
          if (alpha_phi > 0.)
            lowest_alpha_psi = std::max(lowest_alpha_psi,
                                        -0.9 * elastic.shear_modulus()
                                          / (9. * elastic.bulk_modulus() * alpha_phi));
        }
    }



    double
    Material::dilatancy_coefficient(const double porosity) const
    {
      const double t = parameters.dilatancy_factor * (parameters.critical_porosity - porosity);
      return std::clamp(t / std::sqrt(9. + 12. * t * t), lowest_alpha_psi, highest_alpha_psi);
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
