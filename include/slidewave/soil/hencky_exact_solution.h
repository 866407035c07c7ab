#ifndef slidewave_soil_hencky_exact_solution_h
#define slidewave_soil_hencky_exact_solution_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <slidewave/materials/material.h>

namespace slidewave
{
  namespace soil
  {
    /** The exact state of a homogeneous deformation of a Hencky Drucker–Prager material. */
    struct HenckyExactState
    {
      /** The Cauchy stress σ = τ / det F [Pa] (plane strain: xx, yy, xy, zz). */
      dealii::SymmetricTensor<2, 3> cauchy_stress;
      /** det F. */
      double jacobian = 1.;
      /** Whether the state is on the cone (plastic). */
      bool plastic = false;
    };

    /**
     * The closed-form state at time @p t of a stress-free body of a 'hencky drucker
     * prager' material @p material under the constant velocity gradient @p L (plane
     * strain), for the verification of the particle code ('Exact solution = homogeneous
     * deformation'), written apart from materials::HenckyDruckerPrager and
     * soil::FiniteStrainPoints:
     *
     * - F = exp(L t) (a Taylor series with scaling and squaring), b = F F^T with
     *   b_zz = 1, its principal stretches and axes in the plane in closed form;
     * - the Hencky stress τ_A = K tr ε + 2G dev(ε)_A of ε_A = ln λ_A (Eq. 16);
     * - if f(τ) = 3 α_φ p + sqrt(J2) - k_c > 0, the return along the flow rule from the
     *   stress-free state in one step, Δγ = f / (G + 9 K α_φ α_ψ), p -= 3 K α_ψ Δγ,
     *   sqrt(J2) -= G Δγ (the apex when that goes negative);
     * - σ = τ / det F.
     *
     * Exact for every elastic path. A plastic path is exact when its principal axes stay
     * fixed (L symmetric, e.g. plane-strain compression): then the deviatoric direction
     * of the strain is fixed, the return is a projection along a fixed direction onto a
     * fixed line in the (p, sqrt(J2)) plane, and the state reached by many steps is the
     * one-step return of the total strain.
     */
    HenckyExactState
    hencky_homogeneous_state(const materials::MaterialParameters &material,
                             const dealii::Tensor<2, 2>          &L,
                             double                               t);
  } // namespace soil
} // namespace slidewave

#endif
