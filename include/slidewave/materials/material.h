#ifndef slidewave_materials_material_h
#define slidewave_materials_material_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <optional>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/linear_elastic.h>
#include <string>

namespace slidewave
{
  namespace materials
  {
    /** The constitutive models a material can follow. */
    enum class MaterialModel
    {
      linear_elastic,
      drucker_prager,
      /** Finite strain: HenckyDruckerPrager on the points' elastic left Cauchy–Green
       *  tensor (soil::FiniteStrainPoints), not Material::update_stress(). */
      hencky_drucker_prager
    };



    /** How the friction angle of a Drucker–Prager material depends on the shear rate. */
    enum class FrictionLaw
    {
      /** The 'Friction angle' at every rate. */
      constant,
      /** μ(I), I = γ̇ d sqrt(ρ_s / p′) (dry grains; Jop, Forterre and Pouliquen 2006). */
      inertial,
      /** μ(J), J = η_f γ̇ / p′ (grains in a viscous liquid; Boyer, Guazzelli and
       *  Pouliquen 2011, in the same two-angle form). */
      viscous
    };



    /**
     * The parameters of one material of the 2D plane-strain material point
     * method: its name, its model, its density, its elasticity and, for the
     * Drucker–Prager model, its strength (paper 000, §2). Every entry is
     * read and checked whatever the model, so a file does not hide a wrong
     * value behind a model that does not use it.
     */
    struct MaterialParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks; @p path is the subsection path used in error
       * messages. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /**
       * The material in a scene's checkpoint signature: "'name'", and " (finite strain)"
       * for a finite-strain model, whose points carry more properties (a checkpoint of the
       * other kind does not fit; the small-strain signatures are those from before).
       */
      std::string
      signature() const;

      std::string   name            = "soil";
      MaterialModel model           = MaterialModel::drucker_prager;
      double        density         = 2000.;
      double        youngs_modulus  = 1e7;
      double        poisson_ratio   = 0.3;
      double        friction_angle  = 30.;
      double        cohesion        = 0.;
      double        dilatancy_angle = 0.;
      double        tension_cutoff  = 0.;
      /** 'Dilatancy law = critical state': tan psi = K (n_c - n) at the point's porosity
       *  n (Material::dilatancy_coefficient()); otherwise the fixed 'Dilatancy angle'. */
      bool critical_state_dilatancy = false;
      /** The subsection the material was read from, for later messages. */
      std::string path;
      double      critical_porosity = 0.42;
      double      dilatancy_factor  = 4.09;
      /** 'Friction law' and its constants (Material::friction_tangent()). */
      FrictionLaw friction_law              = FrictionLaw::constant;
      double      high_rate_friction_angle  = 40.;
      double      reference_inertial_number = 0.279;
      double      reference_viscous_number  = 0.005;
      double      grain_diameter            = 0.5e-3;
      double      grain_density             = 2500.;
      double      fluid_viscosity           = 1e-3;
    };



    /**
     * Adds the Jaumann (co-rotational) correction of a stress for the spin
     * increment @p spin_increment_xy of one time step (paper 000, Eqs. 5 and
     * 6, integrated with one forward Euler step):
     *
     *   σ ← σ + W σ - σ W,
     *
     * where W is the spin increment, antisymmetric and in the xy plane:
     * W_xy = -W_yx = ω = 1/2 (∂v_x/∂y - ∂v_y/∂x) Δt, all other entries zero.
     * In components, σ_xx += 2 ω σ_xy, σ_yy -= 2 ω σ_xy,
     * σ_xy += ω (σ_yy - σ_xx), σ_xz += ω σ_yz, σ_yz -= ω σ_xz; σ_zz and the
     * trace do not change.
     *
     * Sign check: a rigid rotation counterclockwise (from x towards y) at
     * angular velocity Ω has v = Ω (-y, x), so ω = -Ω Δt; the update is then
     * the first-order expansion of R σ R^T for the rotation R of angle Ω Δt,
     * which turns a uniaxial stress along x towards y. The stress
     * invariants are kept to first order; the relative error in J2 is of
     * order ω^2 per step.
     */
    void
    apply_jaumann_rotation(dealii::SymmetricTensor<2, 3> &stress, double spin_increment_xy);



    /**
     * A material: the parameters it was made from and the constitutive
     * model that turns a material point's strain and spin increments into
     * its new stress. Stresses are in Pa, tension positive, full 3x3 tensors
     * of which plane strain carries xx, yy, xy and zz.
     */
    class Material
    {
    public:
      explicit Material(const MaterialParameters &parameters);

      /**
       * The stress update of one material point over one time step:
       * 1. the Jaumann rotation of the old @p stress by the spin increment
       *    @p spin_increment_xy (see apply_jaumann_rotation());
       * 2. the elastic predictor with @p strain_increment (paper 000, Eq. 2;
       *    its zz component is zero in plane strain);
       * 3. for the Drucker–Prager model, the return mapping of
       *    DruckerPrager, which adds to @p equivalent_plastic_strain.
       * A linear elastic material leaves @p equivalent_plastic_strain alone.
       * Not for MaterialModel::hencky_drucker_prager, whose state is b^e, not a
       * rate of stress (soil::FiniteStrainPoints updates its points).
       */
      void
      update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                    double                               spin_increment_xy,
                    double                              &equivalent_plastic_strain) const;

      /**
       * The same update with the dilatancy coefficient @p alpha_psi of the point's state
       * (dilatancy_coefficient()) instead of the material's fixed one; Drucker–Prager
       * only.
       */
      void
      update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                    double                               spin_increment_xy,
                    double                              &equivalent_plastic_strain,
                    double                               alpha_psi) const;

      /** Whether the friction angle follows the point's shear rate ('Friction law'
       *  inertial or viscous). */
      bool
      rate_dependent_friction() const
      {
        return parameters.friction_law != FrictionLaw::constant;
      }

      /**
       * tan φ at the shear rate @p shear_rate [1/s] and the mean effective pressure
       * @p pressure [Pa] (compression positive) for 'Friction law' inertial or viscous:
       *
       *   tan φ = μ_s + (μ_2 - μ_s) X / (X + X_0),   μ_s = tan φ_s,  μ_2 = tan φ_2,
       *
       * φ_s the 'Friction angle', φ_2 the 'Friction angle at high rate', X the inertial
       * number I = γ̇ d sqrt(ρ_s / p′) or the viscous number J = η_f γ̇ / p′ and X_0 its
       * reference value. μ_s at rest and where p′ <= 0 (at or beyond the apex, where the
       * cohesion alone holds), μ_2 as X grows without bound.
       */
      double
      friction_tangent(double shear_rate, double pressure) const;

      /**
       * The update of update_stress() with the friction of the point's rate
       * (friction_tangent()): the shear rate γ̇ = sqrt(2 e:e)/Δt of the deviator e of
       * @p strain_increment over the step @p dt, the pressure of the elastic trial stress;
       * the cone of that angle (α_φ; k_c stays the static one, so the strength at zero
       * pressure does not fall as φ rises) for this step's return, with
       * @p alpha_psi (NaN: the material's own dilatancy). Drucker–Prager only.
       */
      void
      update_stress_at_rate(dealii::SymmetricTensor<2, 3>       &stress,
                            const dealii::SymmetricTensor<2, 3> &strain_increment,
                            double                               spin_increment_xy,
                            double                              &equivalent_plastic_strain,
                            double                               alpha_psi,
                            double                               dt) const;

      /** Whether the dilatancy follows the point's porosity ('Dilatancy law = critical
       *  state'). */
      bool
      state_dependent_dilatancy() const
      {
        return parameters.critical_state_dilatancy;
      }

      /**
       * The dilatancy coefficient α_ψ = tan ψ / sqrt(9 + 12 tan² ψ) at porosity
       * @p porosity for 'Dilatancy law = critical state': tan ψ = K (n_c - n), positive
       * (dilation) for a packing denser than the critical one, negative (compaction)
       * for a looser one, zero at the critical state; kept within [-α_φ, α_φ] and where
       * the return stays well posed, G + 9 K α_φ α_ψ >= 0.1 G.
       */
      double
      dilatancy_coefficient(double porosity) const;

      /**
       * K + 4G/3 [Pa], which sets the speed of compression waves and thereby
       * the critical time step (paper 000, Eq. 22).
       */
      double
      p_wave_modulus() const;

      /** Whether the model is a finite-strain one (state b^e, no Jaumann rate). */
      bool
      is_finite_strain() const
      {
        return parameters.model == MaterialModel::hencky_drucker_prager;
      }

      /** The parameters the material was made from. */
      const MaterialParameters &
      material_parameters() const
      {
        return parameters;
      }

      /** The mass density [kg/m^3]. */
      double
      density() const;

      /** The name geometry regions refer to the material by. */
      const std::string &
      name() const;

      MaterialModel
      model() const;

      const LinearElastic &
      elasticity() const;

    private:
      MaterialParameters parameters;
      LinearElastic      elastic;
      /** The plastic model; set for MaterialModel::drucker_prager only. */
      std::optional<DruckerPrager> plasticity;
      /** The range of a state-dependent α_ψ (dilatancy_coefficient()). */
      double lowest_alpha_psi = 0., highest_alpha_psi = 0.;
      /** tan φ_s and tan φ_2 of a rate-dependent friction (friction_tangent()). */
      double static_friction, high_rate_friction;
    };
  } // namespace materials
} // namespace slidewave

#endif
