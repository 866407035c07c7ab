#ifndef slidewave_fluid_nodal_grains_coupling_h
#define slidewave_fluid_nodal_grains_coupling_h

#include <array>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>
#include <slidewave/fluid/porous_medium.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/nodal_cell_operator.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * The grains' nodal momentum of a moving skeleton solved together with the water
     * (`Granular water/Drag coupling = semi-implicit consistent`, PorousMedium::nodal_grains).
     *
     * The grains' nodes (the grid's Q1 vertices, masses m_I of the points) take the
     * increment dv = v - v* over their predicted velocity v* (which holds the old
     * pressure's force) from the drag of the new step and the pressure's increment:
     *
     *   (M / dt + D) dv = D u - F v*_s - G (p - p^n),
     *
     * with M = diag(m_I), D_IJ = integral of C N_I N_J (the drag, consistent),
     * (F v*_s)_I = integral of C N_I v*_s and (G p)_I = -(1 - n_I) integral of p grad N_I.
     * The water's equations see the same grains: the drag C (u - v*_s - dv_h) with
     * dv_h = sum_J N_J dv_J, and in the continuity the divergence of the grains' flux
     * sum_J N_J (1 - n_J)(v*_J + dv_J), tested by the pressure's functions, whose
     * increment's part is -G^T. The drag the water loses is exactly what the grains gain,
     * and the work of the pressure's increment on the grains is what the continuity
     * counts, through the open sides too. (The force -G p is the lumped
     * -(1 - n_I) integral of N_I grad p, which the old pressure's force in v* keeps, plus
     * (1 - n_I) times the integral of p N_I n over the grid's boundary: outward for
     * p > 0. On the walls the grains' normal component is held, so only the open sides
     * see it. Without it a tilt of the pressure across a drained top fed a shear of the
     * column that APIC, which hands the grid's velocities back unfiltered, let grow:
     * doc/granular-water.md, "The consistent coupling".)
     *
     * dv is eliminated without a matrix: the water's system is A_w x + B dv(x) = f, with
     * A_w the water's matrix with the Galerkin drag against u (NavierStokesSystem), B the
     * drag's and the flux's columns of dv and dv(x) = (M / dt + D)^-1 (L x + r_0). GMRES
     * iterates on this Schur complement, each product solving the grains' system by
     * conjugate gradients, both components in one run (the cells with grains, their row
     * sums as the preconditioner; to a tolerance that loosens as GMRES converges:
     * relax_products()); the held components, the hanging and the empty nodes (free = 0)
     * are rows of the identity (dv = 0), the hanging nodes take their parents' values. The
     * constrained rows of the water (walls, inflow, hanging nodes) take no coupling term,
     * and their columns enter through the constraints (without their values in the
     * products, with them in the right-hand side).
     *
     * Filled by the water's assembly (begin(), add_cell()), used by its solve (finish(),
     * vmult_add(), compute_increment()), read by the skeleton (increment()).
     */
    class NodalGrainsCoupling
    {
    public:
      using VectorType  = dealii::TrilinosWrappers::MPI::Vector;
      using NodalVector = grid::NodalWorkspace::Vector;

      explicit NodalGrainsCoupling(const grid::BackgroundGrid &grid);

      /** Starts an assembly of a step of length @p dt with the grains @p grains. */
      void
      begin(const NodalGrains &grains, double dt);

      /** The owned cell @p grid_cell (of the grid's DoFHandler) numbered @p cell_number in
       *  tree order, with grains: @p fv the flow's FEValues on it, @p component and
       *  @p vertex each flow shape function's component and vertex, @p drag and @p v_s the
       *  drag coefficient C and the grains' predicted velocity at its quadrature points,
       *  @p fluid_fraction the fluid fraction at its vertices, @p indices its flow
       *  degrees of freedom. */
      void
      add_cell(unsigned int                                        cell_number,
               const dealii::DoFHandler<2>::active_cell_iterator  &grid_cell,
               const dealii::FEValues<2>                          &fv,
               const std::vector<unsigned int>                    &component,
               const std::vector<unsigned int>                    &vertex,
               const std::vector<double>                          &drag,
               const std::vector<dealii::Tensor<1, 2>>            &v_s,
               const std::vector<double>                          &fluid_fraction,
               const std::vector<dealii::types::global_dof_index> &indices);

      /** After the assembly: the flow's constraints @p constraints (kept by the caller
       *  until the solve is done), its cell gather @p gather and the old pressure from
       *  @p flow_old (ghosted, the flow's state 0 before the solve, of the gather's
       *  layout). Subtracts B dv(g) (g: the constraints' values) from @p rhs
       *  (collective). */
      void
      finish(const dealii::AffineConstraints<double> &constraints,
             const linear_algebra::CellGather        &gather,
             const VectorType                        &flow_old,
             VectorType                              &rhs);

      /** y += B dv(x) - B dv(0): the coupling's share of the Schur complement's product
       *  (collective), its inner solve to the tolerance of relax_products(). */
      void
      vmult_add(VectorType &y, const VectorType &x) const;

      /** Before each outer solve (a retried one too): strict products (relax_products())
       *  and the count of iterations_per_product() from zero. */
      void
      start_solve();

      /** The inner solves' relative tolerance for the next products of the outer Krylov
       *  solver, which aims at @p outer_tolerance relative to its right-hand side and
       *  stands at @p residual_ratio of it: a product may be the less accurate, the
       *  further the outer residual has fallen (inexact Krylov: Bouras and Frayssé 2005,
       *  Simoncini and Szyld 2003), 0.1 outer_tolerance / residual_ratio within [1e-12,
       *  1e-3]; with @p strict (a product of the whole iterate: the first, a restart's)
       *  1e-12. */
      void
      relax_products(double outer_tolerance, double residual_ratio, bool strict);

      /** The grains' increment dv of the solved flow @p solution (constraints
       *  distributed; collective): into increment(). */
      void
      compute_increment(const VectorType &solution);

      /** The inner conjugate-gradient iterations per product (vmult_add()) of the last
       *  solve (since start_solve()), their mean (0 without products): what
       *  relax_products() saves shows here (doc/granular-water.md, "The solve"). The same
       *  on every rank. */
      double
      iterations_per_product() const;

      /** The last compute_increment()'s dv (component d in block d, of the nodal
       *  workspace's layout, ghosts and hanging nodes set). */
      const grid::NodalCellOperator::PairVector &
      increment() const
      {
        return dv;
      }


    private:
      /** r = L x (+ r_0 with @p with_known) at the owned nodes, from the ghosted flow
       *  vector @p x (its constrained values set). */
      void
      grains_load(const VectorType &x, bool with_known) const;

      /** dv = (M / dt + D)^-1 r, both components in one solve, to @p tolerance of |r|;
       *  returns its iterations. */
      unsigned int
      solve_grains(double tolerance) const;

      /** The strictest inner tolerance: the step's known part, the increment and the
       *  products of the whole iterate (relax_products()). */
      static constexpr double strict_tolerance = 1e-12;
      /** The products' inner tolerance (start_solve(), relax_products()). */
      double product_tolerance = strict_tolerance;
      /** The products since start_solve() and their inner iterations
       *  (iterations_per_product()). */
      mutable unsigned int products         = 0;
      mutable unsigned int inner_iterations = 0;

      /** out = B dv (owned; the constrained rows' shares to their parents or dropped). */
      void
      water_load(VectorType &out) const;

      const grid::BackgroundGrid &grid;
      NodalGrains                 grains;
      double                      dt = 0.;
      /** A cell with grains: its number in tree order, its flow degrees of freedom (its
       *  nodes and D_IJ are grains_operator's cell of the same index), the continuity's
       *  flux sum_J flux(d, I, J) dv_J(d) in row I (the pressure's force on the grains
       *  (G p)_I = -sum_J flux(d, J, I) p_J), and F v*_s (d, I). */
      struct CellData
      {
        unsigned int                                    cell_number;
        std::array<dealii::types::global_dof_index, 12> indices;
        std::array<double, 32>                          flux;
        std::array<double, 8>                           known;
      };
      std::vector<CellData> cells;
      /** The flow's local degree of freedom of component c at vertex I: position[3 I + c]. */
      std::array<unsigned int, 12> position{};
      /** A cell's grid degrees of freedom (add_cell()'s work space). */
      std::vector<dealii::types::global_dof_index> grid_indices;
      const linear_algebra::CellGather            *gather           = nullptr;
      const dealii::AffineConstraints<double>     *flow_constraints = nullptr;
      /** The old pressure at each cell's vertices (per cell with grains, 4 each). */
      std::vector<double> old_pressure;
      /** The constraints' values g (distribute() of zero). */
      VectorType         values;
      mutable VectorType x_owned, x_ghosted, out;
      /** The grains' load and increment, a component per block (dv ghosted). */
      mutable grid::NodalCellOperator::PairVector load, dv;
      /** M / dt + D, the grains' operator (its cells' matrices D). */
      grid::NodalCellOperator grains_operator;
      NodalVector             sums, inverse_diagonal;
    };
  } // namespace fluid
} // namespace slidewave

#endif
