#ifndef slidewave_materials_hencky_drucker_prager_h
#define slidewave_materials_hencky_drucker_prager_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <slidewave/materials/drucker_prager.h>
#include <slidewave/materials/linear_elastic.h>

namespace slidewave
{
  namespace materials
  {
    /** Where the finite-strain return mapping put the trial state. */
    enum class HenckyReturn
    {
      /** The trial state was admissible: b^e = b^e_trial, no plastic flow. */
      elastic,
      /** The smooth part of the Drucker–Prager cone. */
      cone,
      /** The apex of the cone, p = c cot φ, s = 0 (tension beyond the apex). */
      apex
    };



    /** What one step of HenckyDruckerPrager::update() produced. */
    struct HenckyStep
    {
      HenckyReturn region = HenckyReturn::elastic;

      /** The Kirchhoff stress τ = J σ at the end of the step [Pa]. */
      dealii::SymmetricTensor<2, 3> kirchhoff_stress;

      /** The Cauchy stress σ = τ / J at the end of the step [Pa]. */
      dealii::SymmetricTensor<2, 3> cauchy_stress;

      /**
       * The plastic logarithmic strain increment of the step, ε_trial - ε
       * along the trial principal axes, as a spatial tensor Σ Δε^p_A n_A ⊗ n_A
       * (dimensionless). Its trace is the plastic volume change ln(J^p_new /
       * J^p_old).
       */
      dealii::SymmetricTensor<2, 3> plastic_strain_increment;

      /** sqrt(2/3 dev(Δε^p) : dev(Δε^p)) of the step. */
      double equivalent_plastic_strain_increment = 0.;
    };



    /**
     * Finite-strain elastoplasticity of the soil skeleton of paper 002, §2.2:
     * Hencky hyperelasticity, multiplicative split of the deformation
     * gradient, Drucker–Prager yield with a non-associated flow rule, return
     * mapping in principal logarithmic strains (Simo 1992; de Souza Neto,
     * Perić & Owen, "Computational methods for plasticity", 2008, chapters on
     * Drucker–Prager return mapping and finite-strain elastoplasticity).
     * Tension is positive; stresses in Pa.
     *
     * Equation numbers are those of paper 002, reconstructed from its text
     * (which lost the formulas but refers to Eq. 17 for the yield function).
     *
     * <h3>Kinematics (Eq. 15)</h3>
     * F = F^e F^p. The state of a point is the elastic left Cauchy–Green
     * tensor b^e = F^e F^eT (the identity for an unstressed point). A step
     * with the incremental deformation gradient f = F_{n+1} F_n^-1 has the
     * elastic trial state (plastic flow frozen)
     *
     *   b^e_trial = f b^e_n f^T.
     *
     * With the spectral decomposition b^e_trial = Σ_A λ_A^2 n_A ⊗ n_A
     * (deal.II's eigenvectors(), Jacobi method) the principal logarithmic
     * elastic strains are ε_A = ln λ_A = 1/2 ln(eigenvalue_A).
     *
     * <h3>Hencky energy (Eq. 16)</h3>
     * W = μ Σ_A (ln λ^e_A)^2 + λ/2 (ln J^e)^2, ln J^e = Σ_A ε_A, so the
     * Kirchhoff stress is coaxial with b^e and its principal values are
     *
     *   τ_A = ∂W/∂ε_A = λ tr(ε) + 2 μ ε_A = K tr(ε) + 2 G dev(ε)_A.
     *
     * The Cauchy stress is σ = τ / J with the total J = det F (J = J^e J^p;
     * the plastic volume change of a dilatant flow is not in b^e).
     *
     * <h3>Yield function (Eqs. 17, 18)</h3>
     * In Kirchhoff stress, with p = tr(τ)/3 and J2 = s:s/2, s = dev(τ):
     *
     *   f = 3 α_φ p + sqrt(J2) - k_c,   g = 3 α_ψ p + sqrt(J2).
     *
     * The formulas of Eqs. 17 and 18 are lost from the paper's text; its
     * words (a cohesion c, material constants η, ξ defined from the friction
     * angle, which the text calls ψ, and a potential made by dropping the
     * second and third terms of Eq. 17) fit the usual form
     * f = sqrt(J2) + η p - ξ c with pressure positive in compression. We use the plane-strain match
     * to Mohr–Coulomb of the existing small-strain DruckerPrager (paper 000,
     * Bui et al. 2008): α_φ = tan φ / sqrt(9 + 12 tan^2 φ),
     * k_c = 3 c / sqrt(9 + 12 tan^2 φ), α_ψ likewise from the dilatancy angle
     * ψ (DruckerPrager::plane_strain_coefficient()), i.e. η = 3 α_φ and
     * ξ c = k_c. The paper's non-associated potential, Eq. 17 without its
     * pressure and cohesion terms (g = sqrt(J2), no plastic volume change), is
     * ψ = 0 here; ψ = φ gives associated flow. There is no tension cutoff: the
     * apex p = k_c / (3 α_φ) = c cot φ bounds the mean stress.
     *
     * <h3>Return mapping in principal logarithmic strains</h3>
     * The exponential map integrates the plastic flow
     * Δε^p_A = Δγ ∂g/∂τ_A with the trial eigenvectors kept, so the return is
     * the small-strain return written for the principal values (the elastic
     * law between ε and τ is linear):
     *
     *   ε_A = ε_A,trial - Δγ (α_ψ + s_A / (2 sqrt(J2))),
     *   τ_A = τ_A,trial - Δγ (3 K α_ψ + G s_A / sqrt(J2)).
     *
     * The deviator keeps its direction, sqrt(J2) drops by G Δγ, p by
     * 3 K α_ψ Δγ, and f = 0 gives
     *
     *   Δγ = f_trial / (G + 9 K α_φ α_ψ).
     *
     * The plastic strain increment has the volumetric part 3 α_ψ Δγ and the
     * deviatoric norm |dev Δε^p| = Δγ / sqrt(2): their ratio 3 sqrt(2) α_ψ is
     * fixed by the dilatancy angle.
     *
     * Apex: when the cone return would give sqrt(J2) < 0 (only possible for
     * φ > 0, under tension beyond the apex), the state goes to the apex,
     * p = c cot φ and s = 0, the plastic strain being ε_trial - ε of that
     * state, as de Souza Neto et al. return to the Drucker–Prager apex. The
     * cone return overshoots exactly when p_trial > c cot φ and
     * 9 K α_φ α_ψ sqrt(J2_trial) < G (3 α_φ p_trial - k_c). With φ = 0 the
     * cone is a cylinder without apex (von Mises, sqrt(J2) = c).
     *
     * Update: ε_A = p / (3K) + s_A / (2G) from the returned τ, and
     * b^e_{n+1} = Σ_A exp(2 ε_A) n_A ⊗ n_A with the trial eigenvectors n_A.
     * An elastic step keeps b^e_trial itself, so purely elastic paths are
     * path independent to round-off (hyperelasticity, no rate form, no
     * Jaumann drift under rotation).
     *
     * Plane strain is F_zz = 1 (and f_xz = f_yz = 0); the computation is
     * always in 3D principal space.
     */
    class HenckyDruckerPrager
    {
    public:
      /**
       * The model of Young's modulus @p youngs_modulus [Pa], Poisson ratio
       * @p poisson_ratio, friction angle @p friction_angle_degrees [degrees],
       * cohesion @p cohesion [Pa] and dilatancy angle
       * @p dilatancy_angle_degrees [degrees], the parameters of the
       * small-strain DruckerPrager without its tension cutoff. The values are
       * assumed checked (MaterialParameters::parse_parameters()):
       * E > 0, -1 < ν < 0.5, 0 <= ψ <= φ < 90, c >= 0.
       */
      HenckyDruckerPrager(double youngs_modulus,
                          double poisson_ratio,
                          double friction_angle_degrees,
                          double cohesion,
                          double dilatancy_angle_degrees);

      /**
       * One step: the trial state f b^e f^T of the incremental deformation
       * gradient @p deformation_gradient_increment (det f > 0), the return
       * mapping and the update of @p elastic_left_cauchy_green (b^e, in and
       * out). @p jacobian is det F of the total deformation gradient at the
       * end of the step (> 0), used for σ = τ / J. Adds the step's
       * equivalent plastic strain to @p equivalent_plastic_strain.
       */
      HenckyStep
      update(dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green,
             const dealii::Tensor<2, 3>    &deformation_gradient_increment,
             double                         jacobian,
             double                        &equivalent_plastic_strain) const;

      /**
       * The same step with the dilatancy coefficient @p alpha_psi of the point's state
       * (materials::Material::dilatancy_coefficient(), 'Dilatancy law = critical state')
       * instead of the dilatancy angle's; G + 9 K α_φ α_ψ > 0 (the material keeps it at
       * least 0.1 G).
       */
      HenckyStep
      update(dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green,
             const dealii::Tensor<2, 3>    &deformation_gradient_increment,
             double                         jacobian,
             double                        &equivalent_plastic_strain,
             double                         alpha_psi) const;

      /** The Kirchhoff stress τ of the elastic state @p elastic_left_cauchy_green (Eq. 16). */
      dealii::SymmetricTensor<2, 3>
      kirchhoff_stress(const dealii::SymmetricTensor<2, 3> &elastic_left_cauchy_green) const;

      /**
       * The elastic left Cauchy–Green tensor whose Kirchhoff stress is
       * @p kirchhoff_stress, the inverse of kirchhoff_stress(): the elastic
       * logarithmic strain ε = tr(τ) / (9K) I + dev(τ) / (2G), and
       * b^e = exp(2 ε) along the principal axes of τ. A point that starts with
       * an initial stress starts with this b^e.
       */
      dealii::SymmetricTensor<2, 3>
      elastic_left_cauchy_green(const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const;

      /** f(τ) = α_φ tr(τ) + sqrt(J2(τ)) - k_c [Pa] (Eq. 17). */
      double
      yield_function(const dealii::SymmetricTensor<2, 3> &kirchhoff_stress) const;

      /**
       * The logarithmic strain 1/2 ln b as a spatial tensor (dimensionless);
       * @p left_cauchy_green must be positive definite.
       */
      static dealii::SymmetricTensor<2, 3>
      logarithmic_strain(const dealii::SymmetricTensor<2, 3> &left_cauchy_green);

      /** The friction coefficient α_φ (dimensionless). */
      double
      alpha_phi() const
      {
        return cone.alpha_phi();
      }

      /** The dilatancy coefficient α_ψ (dimensionless). */
      double
      alpha_psi() const
      {
        return cone.alpha_psi();
      }

      /** The cohesion term k_c [Pa]. */
      double
      k_c() const
      {
        return cone.k_c();
      }

      /** The mean stress of the apex, c cot φ [Pa]; +infinity for φ = 0. */
      double
      apex_mean_stress() const
      {
        return cone.apex_mean_stress();
      }

      /** The elastic moduli (K, G, λ) of the Hencky energy. */
      const LinearElastic &
      elasticity() const
      {
        return cone.elasticity();
      }

    private:
      /** The small-strain model's cone and elasticity: its coefficients α_φ, α_ψ, k_c
       *  and moduli are this model's (its return mapping is not used). */
      DruckerPrager cone;
    };
  } // namespace materials
} // namespace slidewave

#endif
