#ifndef slidewave_materials_linear_elastic_h
#define slidewave_materials_linear_elastic_h

#include <deal.II/base/symmetric_tensor.h>

namespace slidewave
{
  namespace materials
  {
    /**
     * Isotropic linear elasticity (Hooke's law) in rate form, the elastic part
     * of paper 000, Eq. 2: an increment of strain produces the increment of
     * stress
     *
     *   dσ = λ tr(dε) I + 2 G dε = K tr(dε) I + 2 G dev(dε).
     *
     * Stress and strain are full 3x3 tensors with tension positive. In plane
     * strain the caller passes increments whose zz (and xz, yz) components are
     * zero; the out-of-plane stress then follows from the in-plane strain,
     * dσ_zz = λ (dε_xx + dε_yy) = ν (dσ_xx + dσ_yy).
     *
     * The moduli are in Pa; strains are dimensionless.
     */
    class LinearElastic
    {
    public:
      /**
       * Elasticity of Young's modulus @p youngs_modulus [Pa] and Poisson ratio
       * @p poisson_ratio. The caller guarantees E > 0 and -1 < ν < 0.5, so
       * that the bulk and shear moduli are positive (checked by
       * MaterialParameters::parse_parameters()).
       */
      LinearElastic(double youngs_modulus, double poisson_ratio);

      /** The stress increment [Pa] produced by @p strain_increment. */
      dealii::SymmetricTensor<2, 3>
      stress_increment(const dealii::SymmetricTensor<2, 3> &strain_increment) const;

      /**
       * The strain that @p stress_increment produces: the inverse of
       * stress_increment(), tr(dσ)/(9K) I + dev(dσ)/(2G). Used to express a
       * plastic correction of the stress as a plastic strain.
       */
      dealii::SymmetricTensor<2, 3>
      strain_increment(const dealii::SymmetricTensor<2, 3> &stress_increment) const;

      /** Bulk modulus K = E / (3 (1 - 2ν)) [Pa]. */
      double
      bulk_modulus() const;

      /** Shear modulus G = E / (2 (1 + ν)) [Pa]. */
      double
      shear_modulus() const;

      /** Lamé's first parameter λ = K - 2G/3 [Pa]. */
      double
      lame_lambda() const;

      /**
       * The P-wave (constrained) modulus K + 4G/3 [Pa]: ρ c_p^2 for the speed
       * c_p of compression waves, used by the critical time step of paper 000,
       * Eq. 22.
       */
      double
      p_wave_modulus() const;

    private:
      double bulk;
      double shear;
    };
  } // namespace materials
} // namespace slidewave

#endif
