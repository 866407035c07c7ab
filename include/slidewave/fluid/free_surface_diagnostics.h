#ifndef slidewave_fluid_free_surface_diagnostics_h
#define slidewave_fluid_free_surface_diagnostics_h

#include <array>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/grid/finite_element_field.h>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * What a user reads off the free-surface flow, computed from the fields on the grid
     * (all collective; the phase field Q1 is bilinear in each square cell, so along a
     * cell edge and along a vertical line through a cell it is linear and its 0.5
     * crossings are found exactly).
     */
    namespace diagnostics
    {
      /** The largest x on the bottom of the domain where phi >= 0.5 (the surge front of
       *  a dam break); the left end when there is none. */
      double
      front_position(const grid::FiniteElementField &phase);

      /** The water surface's elevation at @p x: the highest y on the vertical line x where
       *  phi falls through 0.5 going up; the bottom when no water is there. */
      double
      surface_elevation(const grid::FiniteElementField &phase, double x);

      /** The flow's pressure (component 2 of @p flow, Q1 or Q2) at @p point, evaluated in
       *  the locally owned cell that holds it (the mean of the ranks' values where it lies on
       *  the edge between two ranks' cells); collective. */
      double
      pressure_at(const grid::FiniteElementField &flow, const dealii::Point<2> &point);

      /** The phi = 0.5 contour as segments (x0, y0, x1, y1), marching squares cell by
       *  cell; every rank's segments, sorted, on rank 0 (empty elsewhere). */
      std::vector<std::array<double, 4>>
      surface_segments(const grid::FiniteElementField &phase);

      /** The kinetic energy, integral of rho |u|^2 / 2 [J/m], with rho from phi. */
      double
      kinetic_energy(const grid::FiniteElementField &flow,
                     const grid::FiniteElementField &phase,
                     const FluidProperties          &fluid);

      /** Hydrostatic tank: the largest error of the nodal pressure against the weight
       *  of the column above the node, the model's density rho(phi) of the equilibrium
       *  profile across the surface eta and the air up to the top (the sharp-interface
       *  rho_l |g| (eta - y) away from the surface), relative to rho_l |g| times the
       *  largest depth; and the largest nodal speed [m/s] (the spurious currents). */
      std::array<double, 2>
      hydrostatic_errors(const grid::FiniteElementField &flow,
                         const FreeSurfaceParameters    &parameters);

      /** Poiseuille channel: the largest error of the nodal u_x against
       *  g_x y (H - y) / (2 nu) (y from the bottom, H the channel height, nu of water),
       *  relative to the exact largest value. */
      double
      poiseuille_error(const grid::FiniteElementField &flow,
                       const FreeSurfaceParameters    &parameters);
      /** Darcy flow: the largest error of the nodal u_x against rho_l g_x kappa /
       *  (n mu_l) (n, kappa of the porous structure at the grid's centre), relative. */
      double
      darcy_error(const grid::FiniteElementField &flow, const FreeSurfaceParameters &parameters);

      /** Taylor-Green vortices in the square [x0, x0 + L]^2 with free-slip sides: the L2
       *  error of the velocity at @p time against U (sin k x' cos k y', -cos k x' sin k y')
       *  exp(-2 nu k^2 t) (x' = x - x0, k = pi / L, nu of water, U from 'Initial
       *  water/Velocity'), relative to the exact field's L2 norm. */
      double
      taylor_green_error(const grid::FiniteElementField &flow,
                         const FreeSurfaceParameters    &parameters,
                         double                          time);
    } // namespace diagnostics
  }   // namespace fluid
} // namespace slidewave

#endif
