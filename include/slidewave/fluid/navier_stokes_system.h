#ifndef slidewave_fluid_navier_stokes_system_h
#define slidewave_fluid_navier_stokes_system_h

#include <array>
#include <deal.II/base/index_set.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <optional>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/fluid/nodal_grains_coupling.h>
#include <slidewave/fluid/porous_medium.h>
#include <slidewave/fluid/velocity_subscales.h>
#include <slidewave/grid/finite_element_field.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <slidewave/linear_algebra/cell_scatter.h>
#include <slidewave/linear_algebra/incomplete_lu.h>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /** The two steps' lengths a time step of the fluid needs. */
    struct StepLengths
    {
      /** This step and the one before it (0 at the first step: no extrapolation). */
      double dt = 0., dt_old = 0.;
      /** The flow's own stable step, at least dt (dynamic subscales' time scale; 0: dt). */
      double own_dt = 0.;
    };

    /**
     * The weight w of the Adams-Bashforth advection velocity at t^{n+theta}:
     * u_bar = u^n + w (u^n - u^{n-1}), w = theta dt / dt_old (paper 002, the explicit
     * advection velocity of its Eqs. 56-57); 0 at the first step.
     */
    inline double
    extrapolation_weight(const StepLengths &lengths, const double theta)
    {
      return lengths.dt_old > 0. ? theta * lengths.dt / lengths.dt_old : 0.;
    }

    /** What a linear solve did, and the wall time of its parts [s]. */
    struct SolveReport
    {
      unsigned int iterations = 0;
      double       residual   = 0.;
      /** Assembly, preconditioner set-up (0 when it was kept), GMRES. */
      double assembly_time = 0., preconditioner_time = 0., solve_time = 0.;
      /** With the grains' nodal coupling: the inner conjugate-gradient iterations per
       *  product of the Schur complement (NodalGrainsCoupling::iterations_per_product());
       *  0 without it. */
      double inner_iterations = 0.;
    };

    /**
     * The momentum and continuity equations of the water-air mixture on the background
     * grid (paper 002, Eqs. 9 and 14 with no solid; discrete form Eqs. 25-31, time
     * discretization Eqs. 56-68): equal-order Q1 velocity and pressure stabilized by SUPG
     * and PSPG with tau_m and by the continuity (grad-div) term with tau_cont (Tezduyar's
     * parameters, which paper 002 uses), the theta-scheme for velocity, advection and
     * viscosity, the pressure and the continuity implicit, the advection velocity by
     * Adams-Bashforth from the two last steps. Density and viscosity come from the phase
     * field at t^{n+theta}.
     *
     * The unknowns live in the flow field (a grid::FiniteElementField with the element
     * FESystem(Q1^2, Q1) and two states: state 0 the newest velocity and pressure, state 1
     * the step before); this object holds the linear system and follows the grid: its
     * constraints (hanging nodes, walls) and sparsity are rebuilt whenever the cells change
     * (it is attached after the fields). One solve per step, GMRES with Trilinos' ILU or
     * ML's AMG.
     */
    class NavierStokesSystem : public grid::GridFollower
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      NavierStokesSystem(grid::BackgroundGrid           &grid,
                         grid::FiniteElementField       &flow,
                         const grid::FiniteElementField &phase,
                         const FreeSurfaceParameters    &parameters);

      /**
       * One step: assembles with the flow's states (u^n, u^{n-1}), the phase field before
       * the step @p phase_old (ghosted, the phase field's dofs) and after it (the phase
       * field's state 0), solves for u^{n+1}, p^{n+1} (the inflow sides' velocity that of
       * @p new_time), and shifts the flow's states
       * (collective). Throws RunFailure when GMRES does not converge.
       */
      SolveReport
      step(const VectorType &phase_old, const StepLengths &lengths, double new_time);

      /** The porous solid in the flow (the fields must live on the same grid and outlive
       *  this object); default: none. */
      void
      set_porous_medium(const PorousMedium &medium)
      {
        porous = medium;
        for (linear_algebra::CellGather &gather : porous_gathers)
          gather.clear();
        grains_coupling.reset();
        if (medium.nodal_grains != nullptr)
          grains_coupling = std::make_unique<NodalGrainsCoupling>(grid);
      }

      /** The grains' nodal coupling of the porous medium (PorousMedium::nodal_grains; null
       *  without): after step(), the grains' increment of the step. */
      const NodalGrainsCoupling *
      nodal_grains_coupling() const
      {
        return grains_coupling.get();
      }

      /** Sets the walls', the inflow sides' (at @p time) and the hanging nodes' values in
       *  the state @p state of the flow: an initial field that satisfies the boundary
       *  conditions (collective). */
      void
      impose_boundary_values(unsigned int state, double time);

      /** The largest nodal speed of the newest state (collective). */
      double
      max_speed() const;

      /** The velocity and hanging-node constraints of the current cells. */
      const dealii::AffineConstraints<double> &
      constraints() const
      {
        return flow_constraints;
      }

      void
      grid_ready() override;

      void
      grid_changed() override;

      /** A checkpoint is written: the next step builds its preconditioner afresh, as a run
       *  resumed from this checkpoint does (so that both compute the same). */
      void
      prepare_for_checkpoint() override
      {
        preconditioner.reset();
      }

    private:
      /** The hanging nodes, the walls, the inflow sides' velocity at @p time and, in a
       *  closed tank, the pressure at the lower left corner. */
      void
      make_constraints(double time);

      /** Constraints, sparsity, matrix and vectors for the current cells. */
      void
      setup_system();

      /** The open sides' share of a cell's matrix and right-hand side: the viscous
       *  traction's transposed part, so that (mu grad u - p I) n = 0 there, the backflow
       *  term, and the flux of the drained water relative to a skeleton whose momentum
       *  is eliminated (@p porous_values, null without a porous medium; with the grains'
       *  nodal coupling also into @p nodal_delta and @p nodal_delta_rhs, the terms that
       *  coupling replaces). */
      template <class FlowCell, class PhaseCell>
      void
      add_open_boundary_terms(const FlowCell             &cell,
                              const PhaseCell            &phase_cell,
                              dealii::FEFaceValues<2>    &fv_face,
                              dealii::FEFaceValues<2>    &fv_face_phase,
                              const StepLengths          &lengths,
                              PorousMediumValues         *porous_values,
                              dealii::FullMatrix<double> &local_matrix,
                              dealii::Vector<double>     &local_rhs,
                              dealii::FullMatrix<double> *nodal_delta,
                              dealii::Vector<double>     *nodal_delta_rhs) const;

      /** The Galerkin terms at one quadrature point (@p value, @p gradient, @p component:
       *  the shape functions') of the pointwise elimination that the grains' nodal
       *  coupling replaces, into @p delta and @p delta_rhs. */
      static void
      add_nodal_delta(const PorousCoefficients                &medium,
                      const dealii::Tensor<1, 2>              &grad_p_n,
                      const std::vector<double>               &value,
                      const std::vector<dealii::Tensor<1, 2>> &gradient,
                      const std::vector<unsigned int>         &component,
                      double                                   JxW,
                      dealii::FullMatrix<double>              &delta,
                      dealii::Vector<double>                  &delta_rhs);

      /** The matrix and right-hand side of one step. */
      void
      assemble(const VectorType &phase_old, const StepLengths &lengths);

      grid::BackgroundGrid           &grid;
      grid::FiniteElementField       &flow;
      const grid::FiniteElementField &phase;
      const FreeSurfaceParameters    &parameters;
      PorousMedium                    porous;
      /** The dynamic subscales ('Subscales = dynamic'; null: quasi-static). */
      std::unique_ptr<VelocitySubscales>     subscales;
      dealii::AffineConstraints<double>      flow_constraints;
      dealii::TrilinosWrappers::SparseMatrix matrix;
      VectorType                             rhs, solution;
      /** The flow's preconditioner, kept for 'Preconditioner interval' steps (rebuilt
       *  earlier after a grid change, a checkpoint, a change of the step length or when
       *  GMRES needs many more iterations than with a fresh one). */
      std::shared_ptr<dealii::TrilinosWrappers::PreconditionBase> preconditioner;
      /** The ILU's symbolic factorization, kept while the matrix's sparsity stays
       *  (until the next grid change). */
      std::shared_ptr<linear_algebra::IncompleteLU> ilu;
      /** Where the owned cells' entries and values sit in the matrix, the right-hand
       *  side and the flow's and phase field's ghosted vectors (cleared on grid changes,
       *  rebuilt by the next assembly). */
      linear_algebra::CellScatter scatter;
      linear_algebra::CellGather  flow_gather, phase_gather;
      PorousMediumGathers         porous_gathers;
      /** With the grains' nodal coupling: the coupling and the water's matrix with the
       *  Galerkin drag against u (A_w; `matrix` then holds the pointwise elimination, the
       *  preconditioner's, assembled without its right-hand side). */
      std::unique_ptr<NodalGrainsCoupling>   grains_coupling;
      dealii::TrilinosWrappers::SparseMatrix coupled_matrix;
      bool                                   coupled_matrix_ready = false;
      /** The positions of u_x and u_y of the vertices this rank owns in the owned flow
       *  vector (max_speed(); cleared on grid changes, rebuilt by the next call). */
      mutable std::vector<std::array<int, 2>> vertex_velocity;
      unsigned int                            preconditioner_age = 0;
      /** The iterations of the first counted solve with the preconditioner now in use
       *  (none yet: cleared when it is built). */
      std::optional<unsigned int> fresh_iterations;
      double                      preconditioner_dt = 0.;
    };
  } // namespace fluid
} // namespace slidewave

#endif
