#ifndef slidewave_soil_finite_strain_points_h
#define slidewave_soil_finite_strain_points_h

#include <array>
#include <deal.II/base/array_view.h>
#include <deal.II/base/tensor.h>
#include <limits>
#include <optional>
#include <slidewave/materials/hencky_drucker_prager.h>
#include <slidewave/materials/material.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace soil
  {
    /**
     * The material points of the finite-strain materials ('Model = hencky drucker prager',
     * materials::HenckyDruckerPrager, paper 002 §2.2): their extra state, the elastic left
     * Cauchy–Green tensor b^e (plane strain: xx, yy, xy, zz; the properties
     * 'elastic_left_cauchy_green_*' from @p first_index on, which SoilModel allocates only
     * when a scene uses such a material), and their update from the velocity gradient.
     *
     * Per step, with the point's velocity gradient L (constant over the step):
     *
     *   f = exp(L Δt)                       (in the plane; f_zz = 1, f_xz = f_yz = 0),
     *   f̄ = exp(½ (ε̄_v − tr L Δt)) f       (with B-bar: F-bar, the mean dilatation of the cell),
     *   J_{n+1} = V_{n+1} / V_0,  V_{n+1} = det f̄ V_n = exp(ε̄_v) V_n,
     *
     * then HenckyDruckerPrager::update(b^e, f̄, J_{n+1}) gives b^e_{n+1} and the Cauchy
     * stress σ = τ / J, stored in the point's stress properties (the internal force of the
     * grid uses σ and the current volume as for every material). ε̄_v is the cell's
     * volume-weighted mean of tr L Δt (the small-strain points' B-bar uses the same mean),
     * and ε_v = tr L Δt without B-bar.
     *
     * The exponential rather than I + Δt L: it is the exact increment of a velocity
     * gradient constant over the step (the assumption of the explicit step), so
     * homogeneous deformations are reproduced to round-off (a stretch of 1 after n steps
     * is exp(n L Δt), not (1 + L Δt)^n, whose log strain is off by n (L Δt)² / 2), its
     * determinant exp(tr L Δt) is always positive, and an isochoric flow (tr L = 0) keeps
     * det f = 1 exactly. A 2 x 2 exponential in closed form costs a few transcendental
     * functions, little next to the return mapping's 3 x 3 eigenvectors.
     */
    class FiniteStrainPoints
    {
    public:
      /** The output names of b^e: xx, yy, xy, zz. */
      static const std::array<std::string, 4> &
      property_names();

      /** Whether some material of @p materials is a finite-strain one. */
      static bool
      needed(const std::vector<materials::MaterialParameters> &materials);

      /** The Hencky models of the finite-strain materials of @p materials (indexed like
       *  them); b^e of a point is at @p first_index ... first_index + 3. */
      FiniteStrainPoints(const std::vector<materials::MaterialParameters> &materials,
                         unsigned int                                      first_index);

      /** Whether the points of material @p material_index are updated here. */
      bool
      is_finite_strain(const unsigned int material_index) const
      {
        return models[material_index].has_value();
      }

      /** A new point: b^e = I (for every point; only finite-strain points change it). */
      void
      initialize(std::vector<double> &properties) const;

      /**
       * One step of a finite-strain point @p p: b^e, the stress properties, the
       * equivalent plastic strain and the volume, from the velocity gradient @p L over
       * @p dt; @p volumetric_correction is ε̄_v − tr L Δt (B-bar; 0 without);
       * @p alpha_psi the point's dilatancy coefficient ('Dilatancy law = critical
       * state'), NaN (the default) for the material's own.
       */
      void
      update(dealii::ArrayView<double>   p,
             const dealii::Tensor<2, 2> &L,
             double                      dt,
             double                      volumetric_correction,
             double alpha_psi = std::numeric_limits<double>::quiet_NaN()) const;

      /**
       * b^e of a finite-strain point from its stress properties (an initial stress):
       * the b^e whose Kirchhoff stress is J σ (HenckyDruckerPrager::
       * elastic_left_cauchy_green()), J = V / V_0. Leaves other points alone.
       */
      void
      set_from_stress(dealii::ArrayView<double> p) const;

      /** exp(A) of a 2 x 2 @p A in closed form (Cayley–Hamilton), to round-off. */
      static dealii::Tensor<2, 2>
      exponential(const dealii::Tensor<2, 2> &A);

    private:
      std::vector<std::optional<materials::HenckyDruckerPrager>> models;
      /** The index of b^e_xx; then yy, xy, zz. */
      unsigned int first;
    };
  } // namespace soil
} // namespace slidewave

#endif
