#ifndef slidewave_granular_drag_law_h
#define slidewave_granular_drag_law_h

#include <deal.II/base/tensor.h>

namespace slidewave
{
  namespace granular
  {
    /**
     * The interaction between the granular skeleton and the pore water of
     * paper 002, §2.1: the Kozeny–Carman intrinsic permeability (Eq. 4) and
     * the Forchheimer-like drag (Eq. 3). SI units throughout.
     *
     * <h3>Permeability (Eq. 4)</h3>
     * The paper's formula is lost from its text; it cites Carrier (2003),
     * "Goodbye, Hazen; hello, Kozeny–Carman", J. Geotech. Geoenviron. Eng.
     * 129:1054–1056. We use the Kozeny–Carman relation for spheres of
     * diameter D50 with Carman's constant 180 (Carman 1939; Bear, "Dynamics
     * of fluids in porous media", 1972, Eq. 5.10.18):
     *
     *   k(n) = D50^2 n^3 / (180 (1 - n)^2)   [m^2],
     *
     * with the porosity capped at n_max = 0.99 (paper 002, §3.2, after
     * Eq. 76: "the upper limit value of the solid porosity ... 0.99"), so
     * that k stays finite: k(n >= 0.99) = D50^2 0.99^3 / (180 10^-4)
     * = 53.9 D50^2, against 9.88 10^-4 D50^2 at n = 0.4.
     *
     * <h3>Drag (Eq. 3)</h3>
     * The force per unit mixture volume that the water exerts on the
     * skeleton, with the relative velocity w = v^f - v^s, is
     *
     *   P̂ = C(n, k, |w|) w,
     *   C  = n^2 μ^f / k + n^3 ρ^f F / sqrt(k) |w|,   F = 1.75 / sqrt(150 n^3),
     *
     * the Forchheimer-like law of the two-phase material point method that
     * the paper cites as [23] (Martinelli, Rohe & Soga 2017; also Bandara &
     * Soga 2015), with Ergun's coefficients 150 and 1.75. The first term is
     * Darcy's law: a steady seepage n ∇p^f = -C w gives the Darcy flux
     * n w = -(k / μ^f) ∇p^f when the second term is negligible. The ratio
     * of the two terms is
     *
     *   Forchheimer / Darcy = n ρ^f F sqrt(k) |w| / μ^f,
     *
     * which with k(n) above is 1.75 n Re_p / (sqrt(150 180) (1 - n)) for the
     * particle Reynolds number Re_p = ρ^f |w| D50 / μ^f: the Forchheimer
     * term matters from Re_p of order 10 on and vanishes at low Re_p
     * (Darcy). With Ergun's permeability (constant 150 instead of 180) the
     * ratio is Ergun's 1.75 ρ^f U D50 / (150 μ^f (1 - n)) of the superficial
     * velocity U = n |w|, i.e. the law is Ergun's equation times n. The
     * water feels -P̂.
     *
     * Refused with an InputError that says what is allowed: D50 <= 0,
     * ρ^f <= 0, μ^f <= 0, a porosity outside 0 < n <= 1, a permeability
     * k <= 0, non-finite values.
     */
    class DragLaw
    {
    public:
      /** The cap on the porosity (paper 002, §3.2). */
      static constexpr double porosity_cap = 0.99;

      /** Carman's constant of the Kozeny–Carman relation. */
      static constexpr double kozeny_carman_constant = 180.;

      /** Ergun's viscous (150) and inertial (1.75) coefficients. */
      static constexpr double ergun_viscous_coefficient  = 150.;
      static constexpr double ergun_inertial_coefficient = 1.75;

      /**
       * The law for water of density @p fluid_density [kg/m^3] and dynamic
       * viscosity @p fluid_viscosity [Pa s] in grains of mean diameter
       * @p grain_diameter_d50 [m]. Throws an InputError for values <= 0.
       */
      DragLaw(double fluid_density, double fluid_viscosity, double grain_diameter_d50);

      /**
       * min(n, 0.99) for 0 < @p porosity <= 1; throws an InputError
       * otherwise.
       */
      static double
      capped_porosity(double porosity);

      /** The Kozeny–Carman permeability k(n) [m^2] of Eq. 4, n capped. */
      double
      permeability(double porosity) const;

      /** Ergun's F = 1.75 / sqrt(150 n^3) (dimensionless), n capped. */
      static double
      forchheimer_factor(double porosity);

      /** The Darcy part n^2 μ^f / k of the drag coefficient [kg/(m^3 s)]. */
      double
      darcy_coefficient(double porosity, double permeability) const;

      /**
       * The drag coefficient C [kg/(m^3 s)] of Eq. 3 at porosity
       * @p porosity, permeability @p permeability [m^2] and relative speed
       * @p relative_speed = |v^f - v^s| >= 0 [m/s].
       */
      double
      drag_coefficient(double porosity, double permeability, double relative_speed) const;

      /**
       * The drag P̂ = C w on the skeleton [N/m^3] for the relative velocity
       * @p relative_velocity w = v^f - v^s [m/s].
       */
      template <int dim>
      dealii::Tensor<1, dim>
      drag_force(double                        porosity,
                 double                        permeability,
                 const dealii::Tensor<1, dim> &relative_velocity) const;

      /** Re_p = ρ^f |w| D50 / μ^f of the relative speed @p relative_speed [m/s]. */
      double
      particle_reynolds_number(double relative_speed) const;

      double
      fluid_density() const;

      double
      fluid_viscosity() const;

      double
      grain_diameter() const;

    private:
      double density;
      double viscosity;
      double d50;
    };
  } // namespace granular
} // namespace slidewave

#endif
