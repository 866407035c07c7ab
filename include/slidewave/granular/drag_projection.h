#ifndef slidewave_granular_drag_projection_h
#define slidewave_granular_drag_projection_h

#include <array>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/granular/coupling_gathers.h>
#include <slidewave/granular/skeleton_fluid_exchange.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/nodal_cell_operator.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/velocity_constraints.h>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    /**
     * The skeleton's nodal velocity increment of the semi-implicit coupling, as the
     * water's elimination assumed it (`Drag coupling = semi-implicit projected`).
     *
     * The water eliminates the grains' momentum at each quadrature point
     * (fluid::PorousMedium): with w = rho_b / dt + C (rho_b = rho^s (1 - n)) the grains'
     * velocity there is v = v* + dv,
     *
     *   w dv = C (u - v*) - (1 - n) grad (p - p^n),
     *
     * with the water's new u and p. The grains' nodes take the Q1 field dv_h whose
     * w-weighted projection is that increment,
     *
     *   sum_J (integral of w N_I N_J) dv_J = integral of N_I (C (u - v*) - (1 - n) grad (p - p^n)),
     *
     * with the same fields and quadrature as the water's terms. The grains then gain, summed
     * over the nodes, what the water lost (up to their nodal masses against the integrals of
     * rho_b N_I), and every mode of the grid is coupled alike: where the drag is stiff
     * (dt C >> rho_b) dv_h = u - v*, the grains move with the water node by node
     * (a lumped drag on the grains' side against the water's consistent one instead takes
     * v_I = (M_C u)_I / W_I, a neighbour average of the water's velocity, and smooths the
     * grains once per step: doc/granular-water.md).
     *
     * The system is the weighted mass matrix of the cells with grains, solved by conjugate
     * gradients with its row sums as the preconditioner, without a matrix (cell matrices kept
     * for the solve), once per component; the held components of the skeleton's sides and
     * walls are held in it (rows of the identity), hanging nodes take their parents' values.
     * A cell across which the weight varies (the mass's edge, where the grains thin out) has
     * its matrix lumped in the proportion 1 - w_min / w_max of the variation: there the
     * consistent matrix extrapolates, a node of the light corner taking many times its heavy
     * neighbour's increment with the opposite sign. The row sums, and so the momentum summed
     * over the nodes, are the same either way.
     */
    class DragProjection
    {
    public:
      using Vector = grid::NodalWorkspace::Vector;

      DragProjection(const grid::BackgroundGrid         &grid,
                     const fluid::FreeSurfaceParameters &fluid_parameters,
                     double                              grain_density);

      /** The increment dv_h into @p increment (the nodal workspace's layout, owned values,
       *  ghosts updated), from the water's state 0 (new) and 1 (old pressure) of
       *  @p flow, the phase field's state 0 and the skeleton's fields of this step, for a
       *  step @p dt (collective). */
      void
      increment(const grid::FiniteElementField  &flow,
                const grid::FiniteElementField  &phase,
                const SkeletonFields            &fields,
                const grid::NodalWorkspace      &nodes,
                const grid::VelocityConstraints &constraints,
                double                           dt,
                std::array<Vector, 2>           &increment);

    private:
      /** The cell matrices and right-hand sides of the cells with grains. */
      void
      assemble(const grid::FiniteElementField &flow,
               const grid::FiniteElementField &phase,
               const SkeletonFields           &fields,
               const grid::NodalWorkspace     &nodes,
               double                          dt);

      const grid::BackgroundGrid         &grid;
      const fluid::FreeSurfaceParameters &parameters;
      const double                        grain_density;
      /** The exchange's fields' positions per cell (cleared when the grid changes). */
      CouplingGathers gathers;
      /** The weighted mass matrix of the cells with grains. */
      grid::NodalCellOperator projection;
      /** Per component: 1 on the owned nodes solved for, 0 on held, hanging and empty ones. */
      std::array<Vector, 2> free;
      /** 1 / the row sums (free nodes), 1 elsewhere; the row sums. */
      Vector                inverse_diagonal, sums;
      std::array<Vector, 2> rhs;
    };
  } // namespace granular
} // namespace slidewave

#endif
