#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/vector_tools.h>
#include <slidewave/core/input_error.h>
#include <slidewave/fluid/navier_stokes_system.h>
#include <slidewave/fluid/solid_constraints.h>

namespace slidewave
{
  namespace fluid
  {
    NavierStokesSystem::NavierStokesSystem(grid::BackgroundGrid           &grid,
                                           grid::FiniteElementField       &flow,
                                           const grid::FiniteElementField &phase,
                                           const FreeSurfaceParameters    &parameters)
      : grid(grid)
      , flow(flow)
      , phase(phase)
      , parameters(parameters)
    {
      grid.attach(*this);
      if (parameters.dynamic_subscales)
        subscales = std::make_unique<VelocitySubscales>(grid, parameters.element_degree);
    }



    void
    NavierStokesSystem::grid_ready()
    {
      setup_system();
    }



    void
    NavierStokesSystem::grid_changed()
    {
      setup_system();
    }



    void
    NavierStokesSystem::make_constraints(const double time)
    {
      const auto &dofs = flow.dof_handler();
      flow_constraints.clear();
      flow_constraints.reinit(flow.locally_relevant_dofs());
      dealii::DoFTools::make_hanging_node_constraints(dofs, flow_constraints);
      // The sides: the grid's sides are colourized left 0, right 1, bottom 2, top 3; the
      // normal of the left and right sides is x (component 0), of bottom and top y.
      const auto &sides = parameters.boundaries;
      for (unsigned int side = 0; side < 4; ++side)
        {
          if (sides[side] == FlowBoundary::open || sides[side] == FlowBoundary::inflow)
            continue;
          const unsigned int normal = side < 2 ? 0 : 1;
          std::vector<bool>  mask{false, false, false};
          mask[normal] = true;
          if (sides[side] == FlowBoundary::no_slip)
            mask[1 - normal] = true;
          dealii::VectorTools::interpolate_boundary_values(dofs,
                                                           side,
                                                           dealii::Functions::ZeroFunction<2>(3),
                                                           flow_constraints,
                                                           dealii::ComponentMask(mask));
        }
      // The inflow sides: both velocity components at the time @p time (applied after the
      // walls, so that a corner shared with a wall keeps the wall's zero).
      if (sides.any(FlowBoundary::inflow))
        {
          dealii::FunctionParser<2> inflow(3, time);
          inflow.initialize("x,y,t", sides.inflow_velocity + "; 0", {}, true);
          for (unsigned int side = 0; side < 4; ++side)
            if (sides[side] == FlowBoundary::inflow)
              dealii::VectorTools::interpolate_boundary_values(
                dofs, side, inflow, flow_constraints, dealii::ComponentMask({true, true, false}));
        }
      // Rigid solids hold both velocity components (after the hanging nodes and sides).
      add_solid_constraints(dofs, parameters.solids, 1e-6 * parameters.cell_size, flow_constraints);
      // A closed tank: the pressure is determined up to a constant, set to 0 at the lower
      // left corner (a vertex of every grid, never hanging).
      if (sides.closed())
        for (const auto &cell : dofs.active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(parameters.lower_left) < 1e-9 * parameters.cell_size)
                {
                  const auto dof = cell->vertex_dof_index(v, 2);
                  if (flow_constraints.can_store_line(dof) && !flow_constraints.is_constrained(dof))
                    flow_constraints.add_line(dof);
                }
      flow_constraints.close();
    }



    namespace
    {
      /** The water's system with the grains' nodal momentum eliminated (GMRES' operator). */
      struct SchurComplement
      {
        const dealii::TrilinosWrappers::SparseMatrix &water;
        const NodalGrainsCoupling                    &grains;
        void
        vmult(NodalGrainsCoupling::VectorType &y, const NodalGrainsCoupling::VectorType &x) const
        {
          water.vmult(y, x);
          grains.vmult_add(y, x);
        }
      };
    } // namespace



    void
    NavierStokesSystem::setup_system()
    {
      make_constraints(0.);
      preconditioner.reset(); // it refers to the matrix it was built from
      ilu.reset();
      scatter.clear(); // rebuilt by the next assembly, when every field is current
      flow_gather.clear();
      vertex_velocity.clear();
      phase_gather.clear();
      for (linear_algebra::CellGather &gather : porous_gathers)
        gather.clear();
      flow.reinit_matrix(matrix, flow_constraints);
      coupled_matrix_ready = false;
      rhs.reinit(flow.locally_owned_dofs(), grid.communicator());
      solution.reinit(flow.locally_owned_dofs(), grid.communicator());
    }



    SolveReport
    NavierStokesSystem::step(const VectorType  &phase_old,
                             const StepLengths &lengths,
                             const double       new_time)
    {
      dealii::Timer timer;
      if (parameters.boundaries.any(FlowBoundary::inflow))
        make_constraints(new_time);
      assemble(phase_old, lengths);
      const double assembly_time       = timer.wall_time();
      double       preconditioner_time = 0.;

      // The preconditioner is kept while the matrix stays close to the one it was built
      // for: rebuilt every 'Preconditioner interval' steps, when the step length changed
      // by more than 20 % (the mass term rho / dt dominates the diagonal), when GMRES
      // needed twice the iterations (plus 5) of a fresh one, and after grid changes and
      // checkpoints (setup_system(), prepare_for_checkpoint()). Every condition depends on
      // the computed state only, so a resumed run rebuilds where the uninterrupted one
      // does.
      const auto build = [&]() {
        const double start = timer.wall_time();
        if (parameters.preconditioner == "amg")
          {
            auto amg = std::make_unique<dealii::TrilinosWrappers::PreconditionAMG>();
            dealii::TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic              = false;
            data.higher_order_elements = false;
            data.smoother_sweeps       = 2;
            data.aggregation_threshold = 0.02;
            amg->initialize(matrix, data);
            preconditioner = std::move(amg);
          }
        else
          {
            if (!ilu)
              ilu = std::make_shared<linear_algebra::IncompleteLU>(1);
            ilu->factorize(matrix); // symbolic only after grid changes
            preconditioner = ilu;
          }
        preconditioner_age = 0;
        fresh_iterations.reset();
        preconditioner_dt = lengths.dt;
        preconditioner_time += timer.wall_time() - start;
      };
      const bool stale = !preconditioner || preconditioner_age >= parameters.preconditioner_interval
                         || std::abs(lengths.dt - preconditioner_dt) > 0.2 * preconditioner_dt;
      if (stale)
        build();
      const bool fresh = preconditioner_age == 0;

      const double target = parameters.linear_tolerance * rhs.l2_norm();
      // False when AztecOO stopped at 'loss of precision' without counting (below).
      bool       counted = true;
      const auto solve   = [&]() {
        // The first guess: velocity and pressure extrapolated linearly from the last two
        // steps to t^{n+1} (the last step alone at the first step). GMRES stops at a
        // residual relative to the right-hand side, so a closer guess needs fewer
        // iterations: 30 % fewer on the dam break (doc/free-surface-flow.md, Speed).
        solution = flow.locally_owned_values(0);
        if (lengths.dt_old > 0.)
          {
            const double ratio = lengths.dt / lengths.dt_old;
            solution.sadd(1. + ratio, -ratio, flow.locally_owned_values(1));
          }
        dealii::SolverControl control(parameters.max_iterations, std::max(target, 1e-300));
        if (grains_coupling)
          {
            // The Schur complement of the grains' nodal coupling, A_w + B (M / dt + D)^-1 L
            // (NodalGrainsCoupling), without a matrix; preconditioned by the pointwise
            // elimination's matrix, which approximates it. Right preconditioning: GMRES
            // monitors the unpreconditioned residual (up to the inner solves' accuracy).
            // Its products' inner solves need only the accuracy of what is left of the
            // residual (NodalGrainsCoupling::relax_products): loose as GMRES converges, and
            // strict for the products of the whole iterate, whose error enters the
            // residual itself: the first (b - A x0) and the one that starts a restart. The
            // slot runs before each product and, at a restart, twice with the same step
            // (before the restart's product and before the new cycle's first).
            const SchurComplement           schur{coupled_matrix, *grains_coupling};
            constexpr unsigned int          restart = 50;
            dealii::SolverGMRES<VectorType> gmres(
              control, dealii::SolverGMRES<VectorType>::AdditionalData(restart + 2, true));
            const double outer     = parameters.linear_tolerance;
            unsigned int last_step = dealii::numbers::invalid_unsigned_int;
            grains_coupling->start_solve();
            gmres.connect([&](const unsigned int step, const double residual, const VectorType &) {
              const bool restarting = step > 0 && step % restart == 0 && step != last_step;
              last_step             = step;
              grains_coupling->relax_products(outer, residual * outer / target, restarting);
              return dealii::SolverControl::success;
            });
            gmres.solve(schur, solution, rhs, *preconditioner);
            return SolveReport{control.last_step(), control.last_value()};
          }
        dealii::TrilinosWrappers::SolverGMRES gmres(
          control, dealii::TrilinosWrappers::SolverGMRES::AdditionalData(false, 50));
        try
          {
            gmres.solve(matrix, solution, rhs, *preconditioner);
          }
        catch (const dealii::ExceptionBase &)
          {
            // AztecOO stops with 'loss of precision' when its recursive residual met the
            // target and the true one cannot (a target at round-off, such as a tolerance
            // of 1e-12): the iterate is then as accurate as the arithmetic allows. It is
            // kept when its true residual is within 1e-8 of the right-hand side; anything
            // else (a breakdown, non-finite entries) fails below.
            VectorType   residual(rhs);
            const double true_residual = matrix.residual(residual, solution, rhs);
            if (!(true_residual <= 1e-8 * rhs.l2_norm()))
              throw;
            // AztecOO leaves the control unchecked when it stops so: the iterations it took
            // are unknown (the control's count is numbers::invalid_unsigned_int), and 0 is
            // reported, as for a guess already at the target, and kept out of the
            // preconditioner's bookkeeping below.
            const unsigned int steps = control.last_step();
            counted                  = steps != dealii::numbers::invalid_unsigned_int;
            return SolveReport{counted ? steps : 0u, true_residual};
          }
        return SolveReport{control.last_step(), control.last_value()};
      };
      SolveReport report;
      try
        {
          try
            {
              report = solve();
            }
          catch (const dealii::SolverControl::NoConvergence &)
            {
              if (fresh)
                throw;
              build(); // a kept preconditioner that no longer serves: once more, fresh
              report = solve();
            }
        }
      catch (const dealii::SolverControl::NoConvergence &failure)
        {
          throw RunFailure("the flow's linear solver (GMRES) did not converge: residual "
                           + to_string(failure.last_residual) + " after "
                           + std::to_string(failure.last_step) + " iterations, target "
                           + to_string(target)
                           + " (reduce 'Time stepping/Courant number' or 'Maximum time "
                             "step', or raise 'Linear solver/Maximum iterations')");
        }
      catch (const dealii::ExceptionBase &)
        {
          // AztecOO's breakdown: a system with non-finite or degenerate entries.
          throw RunFailure("the flow's linear solver (GMRES) broke down: the system is "
                           "degenerate or not finite (reduce the time step)");
        }
      report.assembly_time       = assembly_time;
      report.preconditioner_time = preconditioner_time;
      report.solve_time          = timer.wall_time() - assembly_time - preconditioner_time;
      if (grains_coupling)
        report.inner_iterations = grains_coupling->iterations_per_product();
      // A preconditioner that takes more than twice its first counted solve's iterations
      // (plus 5) is rebuilt at the next step; a solve whose count is unknown judges
      // nothing and sets no reference.
      if (counted && !fresh_iterations)
        fresh_iterations = report.iterations;
      else if (counted && report.iterations > 2 * *fresh_iterations + 5)
        preconditioner.reset();
      ++preconditioner_age;
      flow_constraints.distribute(solution);
      if (grains_coupling)
        grains_coupling->compute_increment(solution);

      flow.locally_owned_values(1) = flow.locally_owned_values(0);
      flow.values_changed(1);
      flow.locally_owned_values(0) = solution;
      flow.values_changed(0);
      if (subscales)
        subscales->update(flow, flow_gather);
      return report;
    }



    void
    NavierStokesSystem::impose_boundary_values(const unsigned int state, const double time)
    {
      make_constraints(time);
      flow_constraints.distribute(flow.locally_owned_values(state));
      flow.values_changed(state);
    }



    double
    NavierStokesSystem::max_speed() const
    {
      // The largest nodal speed over the vertices (the velocity's nodes of Q1; the
      // corners of Q2), read where this rank owns them (every vertex is owned by one rank).
      const auto &u = flow.locally_owned_values(0);
      if (vertex_velocity.empty() && u.locally_owned_size() > 0)
        {
          const Epetra_BlockMap &map   = u.trilinos_vector().Map();
          const auto             owned = flow.locally_owned_dofs();
          std::vector<bool>      seen(owned.n_elements(), false);
          for (const auto &cell : flow.dof_handler().active_cell_iterators())
            if (cell->is_locally_owned())
              for (const unsigned int v : cell->vertex_indices())
                {
                  const auto ux = cell->vertex_dof_index(v, 0), uy = cell->vertex_dof_index(v, 1);
                  if (!owned.is_element(ux) || seen[owned.index_within_set(ux)])
                    continue;
                  seen[owned.index_within_set(ux)] = true;
                  using IntType                    = dealii::TrilinosWrappers::types::int_type;
                  vertex_velocity.push_back(
                    {{map.LID(static_cast<IntType>(ux)), map.LID(static_cast<IntType>(uy))}});
                }
        }
      const double *values  = u.trilinos_vector()[0];
      double        fastest = 0.;
      for (const auto &[x, y] : vertex_velocity)
        fastest = std::max(fastest, std::sqrt(values[x] * values[x] + values[y] * values[y]));
      return dealii::Utilities::MPI::max(fastest, grid.communicator());
    }
  } // namespace fluid
} // namespace slidewave
