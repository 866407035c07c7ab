#ifndef slidewave_granular_skeleton_fluid_exchange_h
#define slidewave_granular_skeleton_fluid_exchange_h

#include <array>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/granular/coupling_gathers.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/velocity_constraints.h>

namespace slidewave
{
  namespace granular
  {
    /** The fields of the moving skeleton that the water's equations read (paper 002,
     *  Eqs. 25–31): all Q1 on the shared grid, owned by the fluid's solver. */
    struct SkeletonFields
    {
      grid::FiniteElementField *fluid_fraction       = nullptr;
      grid::FiniteElementField *inverse_permeability = nullptr;
      grid::FiniteElementField *solid_flux           = nullptr;
      /** The flux (1 - n) v^n of the skeleton's velocity at the step's start, for the water's
       *  phase field, when solid_flux holds the predicted v* (semi-implicit coupling;
       *  null: the phase field reads solid_flux). The flow solved last had this v^n in
       *  its continuity, so the phase field's mixture divergence with it is the one the
       *  water's velocity satisfies. */
      grid::FiniteElementField *start_flux = nullptr;
    };

    /**
     * The exchange between the skeleton's points and the water at the nodes of the grid
     * they share (paper 002, §3.5, steps (i) and (iv)):
     *
     * - to the water: from the nodal sums of the skeleton (mass, momentum, solid volume
     *   S_I, drag D_I; PorousSkeletonModel) the fluid fraction n_I = 1 - S_I / A_I (at
     *   least 0.01), the inverse permeability 1/kappa_I = D_I / (A_I n_I^2 mu^w), so that
     *   the water's drag n^2 mu / kappa is the points' drag where the pores hold water,
     *   and the solid's flux (1 - n_I) v_I (zero on empty nodes, the skeleton's sides and
     *   walls held): a flux, not a velocity, so that a node the grains barely touch, whose
     *   velocity GIMP's gradients may make arbitrary on its tiny mass, hands over a tiny
     *   flux. v_I is momentum / mass (explicit coupling) or the predicted v*_I =
     *   (momentum + dt (f_I + f^p_I)) / m_I with the old pressure's force (semi-implicit);
     * - to the skeleton: the force of the water on the grains at each node,
     *
     *     f_I = -(1 - n_I) integral of grad p N_I + integral of C (u - v_s) N_I,
     *     C = n^2 mu(phi) / kappa,
     *
     *   with the water's new pressure and velocity and the same fields and quadrature as
     *   the water's own -n grad p and -C (u - v_s) (NavierStokesSystem): the drag equal
     *   and opposite, the pressure's force lumped on the node's grains (1 - n_I), so that
     *   its acceleration is -grad p / rho^s however little mass the node has. Explicit
     *   coupling: the drag is explicit in the solid's velocity (stable for steps below
     *   about rho^s (1 - n) k / mu). Semi-implicit coupling (the default): the water
     *   eliminates the skeleton's momentum (fluid::PorousMedium); the skeleton gets the
     *   force without - C v_s and the nodal drag W_I = integral of C N_I, which its nodes
     *   take implicitly, so that the drag it feels is C (u - v) with its own velocity of
     *   the new step.
     */
    class SkeletonFluidExchange
    {
    public:
      SkeletonFluidExchange(const grid::BackgroundGrid         &grid,
                            const fluid::FreeSurfaceParameters &fluid_parameters);

      /** The water's fields from the skeleton's nodal sums of this step (after the
       *  engine's begin_step(); collective). @p empty_mass: nodes with less are empty.
       *  @p predictor_step > 0 (semi-implicit): the solid velocity is v^n + dt (f + f_p)
       *  / m with this dt, f_p the force of the pressure of @p flow's state 0 on the
       *  grains (pressure_force()); 0: v^n. */
      void
      to_fluid(const grid::NodalWorkspace      &nodes,
               const grid::VelocityConstraints &constraints,
               double                           empty_mass,
               const SkeletonFields            &fields,
               double                           predictor_step = 0.,
               const grid::FiniteElementField  *flow           = nullptr);

      /** The water's force on the skeleton at the nodes, from the water's state 0 (its
       *  new velocity and pressure) and @p phase (state 0), into @p force, vectors of the
       *  nodal workspace's layout (owned totals; collective). With @p water_drag (same
       *  layout), the semi-implicit coupling: the force without - C v_s, and W_I into
       *  @p water_drag. On an adaptive grid what lands on a hanging node goes to its
       *  parents (@p nodes' condensation), as the points' own sums do. */
      void
      to_skeleton(const grid::FiniteElementField              &flow,
                  const grid::FiniteElementField              &phase,
                  const SkeletonFields                        &fields,
                  const grid::NodalWorkspace                  &nodes,
                  std::array<grid::NodalWorkspace::Vector, 2> &force,
                  grid::NodalWorkspace::Vector                *water_drag = nullptr);

      /** The relative speed |u - v_s| of the water's state 0 and the skeleton's velocity
       *  field at the owned nodes of this step's points, into @p speed (the skeleton's
       *  nodal field the points gather for the Forchheimer drag), ghosts updated
       *  (collective). */
      void
      relative_speed(const grid::FiniteElementField &flow,
                     const SkeletonFields           &fields,
                     const grid::NodalWorkspace     &nodes,
                     grid::NodalWorkspace::Vector   &speed) const;

      /** The old pressure's force on the grains that to_fluid() put in the predicted
       *  velocity (semi-implicit; owned values; valid until to_skeleton()). */
      const std::array<grid::NodalWorkspace::Vector, 2> &
      predictor_pressure_force() const
      {
        return pressure_work;
      }

    private:
      /** The pressure's force on the grains of each node, lumped: -(1 - n_I) times the
       *  integral of N_I grad p, with the pressure of @p flow's state 0 and the nodes' fluid
       *  fraction of this step (to_fluid()), into @p force (owned totals; collective). */
      void
      pressure_force(const grid::FiniteElementField              &flow,
                     const SkeletonFields                        &fields,
                     const grid::NodalWorkspace                  &nodes,
                     std::array<grid::NodalWorkspace::Vector, 2> &force);

      /** Completes @p force (integrals of N_I grad p; hanging nodes' shares to their
       *  parents, then compressed here) and scales each owned node's by its solid
       *  fraction 1 - n_I: the force on its grains. */
      void
      lump_on_grains(const grid::NodalWorkspace                  &nodes,
                     std::array<grid::NodalWorkspace::Vector, 2> &force) const;

      const grid::BackgroundGrid         &grid;
      const fluid::FreeSurfaceParameters &parameters;
      /** The nodal workspace's vectors of to_fluid() (kept between steps). */
      grid::NodalWorkspace::Vector                fraction, inverse_permeability, vx, vy;
      std::array<grid::NodalWorkspace::Vector, 2> pressure_work;
      /** The fields' positions per cell (cleared when the grid changes). */
      CouplingGathers gathers;
    };
  } // namespace granular
} // namespace slidewave

#endif
