#ifndef slidewave_materials_drucker_prager_h
#define slidewave_materials_drucker_prager_h

#include <deal.II/base/symmetric_tensor.h>
#include <slidewave/materials/linear_elastic.h>

namespace slidewave
{
  namespace materials
  {
    /** Which part of the elastic domain's boundary a stress was returned to. */
    enum class ReturnRegion
    {
      /** The trial stress was admissible: no plastic flow. */
      elastic,
      /** The smooth part of the Drucker–Prager cone. */
      cone,
      /** The tension cutoff plane p = T, deviator unchanged. */
      tension_cutoff,
      /**
       * A point where the deviator is scaled and the mean stress fixed: the
       * apex of the cone when the cutoff lies beyond it, otherwise the circle
       * where the cone meets the cutoff plane.
       */
      corner
    };



    /** What one return mapping did to a stress. */
    struct PlasticCorrection
    {
      ReturnRegion region = ReturnRegion::elastic;

      /**
       * The plastic strain increment Δε^p = D^-1 : (σ_trial - σ), the part of
       * the strain increment that produced no stress (dimensionless).
       */
      dealii::SymmetricTensor<2, 3> plastic_strain_increment;

      /**
       * The increment of the equivalent plastic strain,
       * sqrt(2/3 dev(Δε^p) : dev(Δε^p)); see
       * DruckerPrager::equivalent_plastic_strain().
       */
      double equivalent_plastic_strain_increment = 0.;
    };



    /**
     * The cone of one return: the friction coefficient α_φ and the cohesion term k_c of
     * f = α_φ I1 + sqrt(J2) - k_c. A material's own (DruckerPrager::cone()) or one of a
     * friction that depends on the point's shear rate (Material::update_stress_at_rate()).
     */
    struct Cone
    {
      double alpha_phi = 0.;
      double k_c       = 0.;
    };



    /**
     * Linear elasticity with the non-associative Drucker–Prager yield
     * criterion and a tension cutoff on the mean stress, integrated with a
     * closed-form return mapping (paper 000, §2, Eqs. 2–4).
     *
     * <h3>Surfaces</h3>
     * With tension positive, I1 = tr σ = 3p and J2 = s:s/2 for the deviator
     * s = σ - p I, the yield function and the plastic potential are (paper
     * 000, Eq. 3)
     *
     *   f = α_φ I1 + sqrt(J2) - k_c,   g = α_ψ I1 + sqrt(J2),
     *
     * with the plane-strain match to Mohr–Coulomb of Bui et al. (2008), see
     * VERIFICATION.md: α_φ = tan φ / sqrt(9 + 12 tan^2 φ),
     * k_c = 3 c / sqrt(9 + 12 tan^2 φ), and α_ψ from the dilatancy angle ψ
     * like α_φ. The cone opens towards compression; for φ > 0 its apex lies
     * on the hydrostatic axis at p = k_c / (3 α_φ) = c cot φ. A second
     * surface bounds the mean stress by the tension cutoff T >= 0: p <= T.
     *
     * <h3>Return on the cone</h3>
     * The plastic strain increment is Δλ ∂g/∂σ = Δλ (α_ψ I + s / (2
     * sqrt(J2))), so the stress is corrected by
     * -Δλ (3 K α_ψ I + G s / sqrt(J2)) (paper 000, Eq. 4, whose volumetric
     * term carries α_ψ here because the flow follows g; the two agree for
     * ψ = φ). The correction is radial in the deviatoric plane: the deviator
     * keeps its direction and Lode angle, sqrt(J2) drops by G Δλ and I1 by
     * 9 K α_ψ Δλ. Asking f = 0 afterwards gives Δλ in closed form:
     *
     *   Δλ = f_trial / (G + 9 K α_φ α_ψ).
     *
     * With ψ = φ this is the closest point of the cone in the energy norm
     * (σ : D^-1 : σ).
     *
     * <h3>Apex, cutoff and corner</h3>
     * In the (p, sqrt(J2)) plane all corrections keep the deviatoric
     * direction, and the three flow directions (cone: (3 K α_ψ, G); cutoff:
     * (1, 0), associated; corner: any combination of the two) split the
     * inadmissible states into regions, tried in this order:
     * - cone: the return above ends with sqrt(J2) >= 0 and p <= T;
     * - tension cutoff: otherwise, if p_trial > T and the point
     *   (T, sqrt(J2_trial)) is inside the cone, the mean stress is put back
     *   to T and the deviator is kept (tensile failure does not erase the
     *   shear stress the cone still allows);
     * - corner: otherwise the mean stress goes to p* = min(T, c cot φ) and
     *   sqrt(J2) to k_c - 3 α_φ p*, again along the trial deviator's
     *   direction. When T >= c cot φ this is the apex of the cone, s = 0 and
     *   I1 = k_c / α_φ: the return used when the cone correction would
     *   overshoot the apex (sqrt(J2) would become negative). A cutoff beyond
     *   the apex therefore never acts.
     * This is the treatment of tension cracking of Bui et al. (2008) (mean
     * stress moved back to the admissible limit, shear then scaled onto the
     * cone), generalised to a cutoff T below the apex and written as a
     * return mapping, so that the plastic strain of every correction is
     * defined.
     *
     * <h3>φ = 0: undrained clay</h3>
     * With φ = 0 (and therefore ψ = 0) the cone becomes the von Mises
     * cylinder sqrt(J2) = k_c = c and has no apex; the return scales the
     * deviator to sqrt(J2) = c and leaves the mean stress alone (no plastic
     * volume change), as a total stress analysis of undrained clay requires.
     * Because the match is made in plane strain, c is the undrained shear
     * strength s_u: in plane-strain plastic flow the out-of-plane deviatoric
     * stress vanishes (s_zz = 0, otherwise the plastic strain rate would
     * have a zz part), the principal stresses are p + τ, p, p - τ, so
     * sqrt(J2) = τ = (σ_1 - σ_3) / 2, the Tresca strength. The cutoff is the
     * only limit on the mean stress then; φ = c = 0 gives an inviscid fluid
     * (s = 0 after every return).
     *
     * <h3>Equivalent plastic strain</h3>
     * The accumulated measure is the von Mises equivalent of the deviatoric
     * plastic strain increments, Σ sqrt(2/3 dev(Δε^p) : dev(Δε^p)): on the
     * cone dev(Δε^p) = Δλ s / (2 sqrt(J2)), so each step adds Δλ / sqrt(3);
     * the cutoff adds nothing (its flow is volumetric); the corner adds the
     * deviatoric strain the scaling of s removed. It is a state variable for
     * output only: the model has no hardening.
     */
    class DruckerPrager
    {
    public:
      /**
       * The model of Young's modulus @p youngs_modulus [Pa], Poisson ratio
       * @p poisson_ratio, friction angle @p friction_angle_degrees [degrees],
       * cohesion @p cohesion [Pa], dilatancy angle @p dilatancy_angle_degrees
       * [degrees] and tension cutoff @p tension_cutoff [Pa], the largest
       * mean stress p = I1/3 the material carries. The values are assumed
       * checked (MaterialParameters::parse_parameters()):
       * 0 <= ψ <= φ < 90, c >= 0, T >= 0.
       */
      DruckerPrager(double youngs_modulus,
                    double poisson_ratio,
                    double friction_angle_degrees,
                    double cohesion,
                    double dilatancy_angle_degrees,
                    double tension_cutoff);

      /**
       * Elastic predictor and return mapping for one step: adds the elastic
       * response to @p strain_increment to @p stress [Pa], returns the result
       * to the admissible domain and adds the increment of the equivalent
       * plastic strain to @p equivalent_plastic_strain.
       */
      PlasticCorrection
      update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                    double                              &equivalent_plastic_strain) const;

      /**
       * Returns the trial stress @p stress [Pa] to the admissible domain
       * f <= 0, p <= T in place, as described in the class documentation.
       * A stress already admissible (up to a relative rounding tolerance of
       * 1e-12) is left untouched.
       */
      PlasticCorrection
      return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress) const;

      /** update_stress() and return_to_yield_surface() with the dilatancy coefficient
       *  @p alpha_psi instead of the model's own (a state-dependent dilatancy,
       *  Material::dilatancy_coefficient()). */
      PlasticCorrection
      update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                    double                              &equivalent_plastic_strain,
                    double                               alpha_psi) const;

      PlasticCorrection
      return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress, double alpha_psi) const;

      /** update_stress() and return_to_yield_surface() on the cone @p cone (a friction that
       *  depends on the rate; the tension cutoff is the model's) with the dilatancy
       *  coefficient @p alpha_psi. With cone() and alpha_psi() they are the plain ones, bit
       *  for bit. */
      PlasticCorrection
      update_stress(dealii::SymmetricTensor<2, 3>       &stress,
                    const dealii::SymmetricTensor<2, 3> &strain_increment,
                    double                              &equivalent_plastic_strain,
                    const Cone                          &cone,
                    double                               alpha_psi) const;

      PlasticCorrection
      return_to_yield_surface(dealii::SymmetricTensor<2, 3> &stress,
                              const Cone                    &cone,
                              double                         alpha_psi) const;

      /** The model's own cone, α_φ and k_c. */
      Cone
      cone() const;

      /** The cone of friction angle tan φ = @p tangent and cohesion @p cohesion [Pa]: the
       *  plane-strain match α_φ = t / sqrt(9 + 12 t²), k_c = 3 c / sqrt(9 + 12 t²). */
      static Cone
      cone_of_tangent(double tangent, double cohesion);

      /** f(σ) = α_φ I1 + sqrt(J2) - k_c [Pa] (paper 000, Eq. 3). */
      double
      yield_function(const dealii::SymmetricTensor<2, 3> &stress) const;

      /** The friction coefficient α_φ (dimensionless). */
      double
      alpha_phi() const;

      /** The dilatancy coefficient α_ψ (dimensionless). */
      double
      alpha_psi() const;

      /** The cohesion term k_c [Pa]. */
      double
      k_c() const;

      /**
       * The mean stress at the apex of the cone, c cot φ [Pa]; +infinity for
       * φ = 0, where the cone is a cylinder.
       */
      double
      apex_mean_stress() const;

      /** The tension cutoff T [Pa] on the mean stress. */
      double
      tension_cutoff() const;

      const LinearElastic &
      elasticity() const;

      /**
       * sqrt(2/3 dev(ε) : dev(ε)), the von Mises equivalent of the strain
       * (increment) @p strain.
       */
      static double
      equivalent_plastic_strain(const dealii::SymmetricTensor<2, 3> &strain);

      /**
       * The coefficient tan θ / sqrt(9 + 12 tan^2 θ) of the plane-strain
       * match for an angle @p angle_degrees [degrees]: α_φ for the friction
       * angle, α_ψ for the dilatancy angle.
       */
      static double
      plane_strain_coefficient(double angle_degrees);

    private:
      LinearElastic elastic;
      double        friction_coefficient;
      double        dilatancy_coefficient;
      double        cohesion_term;
      double        cutoff;
    };
  } // namespace materials
} // namespace slidewave

#endif
