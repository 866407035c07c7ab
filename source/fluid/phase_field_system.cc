#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/vector.h>
#include <slidewave/core/input_error.h>
#include <slidewave/fluid/phase_field_system.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_evaluation.h>
#include <stdexcept>

namespace slidewave
{
  namespace fluid
  {
    PhaseFieldSystem::PhaseFieldSystem(grid::BackgroundGrid           &grid,
                                       const grid::FiniteElementField &flow,
                                       grid::FiniteElementField       &phase,
                                       const FreeSurfaceParameters    &parameters)
      : grid(grid)
      , flow(flow)
      , phase(phase)
      , parameters(parameters)
    {
      grid.attach(*this);
    }



    void
    PhaseFieldSystem::set_porous_medium(const PorousMedium &medium)
    {
      // The phase field needs the fluid fraction and the solid's flux; not the drag.
      porous                      = medium;
      porous.inverse_permeability = nullptr;
      porous.grain_density        = 0.;
      for (linear_algebra::CellGather &gather : porous_gathers)
        gather.clear();
    }



    unsigned int
    PhaseFieldSystem::gauss_points() const
    {
      // Two points integrate div(u phi) and u . n phi exactly for Q1 and Q2 velocities
      // (degree 3 in each variable); in the pores n u phi has one degree more, which Q2
      // velocities take beyond two points.
      return porous.active() ? std::max(2u, flow.finite_element().degree + 1) : 2;
    }



    void
    PhaseFieldSystem::grid_ready()
    {
      setup_system();
    }



    void
    PhaseFieldSystem::grid_changed()
    {
      setup_system();
    }



    void
    PhaseFieldSystem::setup_system()
    {
      const MPI_Comm communicator = grid.communicator();
      phase.reinit_matrix(matrix, phase.constraints());
      ilu.reset();     // bound to the matrix's sparsity
      scatter.clear(); // rebuilt by the next assembly, when every field is current
      phase_gather.clear();
      flow_gather.clear();
      for (linear_algebra::CellGather &gather : porous_gathers)
        gather.clear();
      rhs.reinit(phase.locally_owned_dofs(), communicator);
      solution.reinit(phase.locally_owned_dofs(), communicator);
      phase_old.reinit(phase.locally_owned_dofs(), phase.locally_relevant_dofs(), communicator);
      phase_old = phase.values(0);
    }



    void
    PhaseFieldSystem::assemble(const StepLengths &lengths, const double gamma)
    {
      const auto             &fe = phase.finite_element();
      const dealii::QGauss<2> quadrature(gauss_points());
      const unsigned int      n_q = quadrature.size(), n_dofs = fe.n_dofs_per_cell();
      dealii::FEValues<2>     fv(fe,
                             quadrature,
                             dealii::update_values | dealii::update_gradients
                               | dealii::update_JxW_values);
      dealii::FEValues<2>     fv_flow(flow.finite_element(),
                                  quadrature,
                                  dealii::update_values | dealii::update_gradients);
      const dealii::FEValuesExtractors::Vector velocity(0);
      const dealii::QGauss<1>                  face_quadrature(gauss_points());
      dealii::FEFaceValues<2>                  fv_face(fe,
                                      face_quadrature,
                                      dealii::update_values | dealii::update_quadrature_points
                                        | dealii::update_normal_vectors
                                        | dealii::update_JxW_values);
      dealii::FEFaceValues<2>                  fv_face_flow(flow.finite_element(),
                                           face_quadrature,
                                           dealii::update_values);
      std::vector<dealii::Tensor<1, 2>>        u_face_n(face_quadrature.size()),
        u_face_old(face_quadrature.size());
      std::vector<double> phi_face_n(face_quadrature.size());
      // The porous solid's fluid fraction and flux (only when there is one).
      std::unique_ptr<PorousMediumValues> porous_values;
      if (porous.active())
        porous_values = std::make_unique<PorousMediumValues>(
          grid, porous, quadrature, face_quadrature, &porous_gathers);
      const std::vector<double> no_viscosity(std::max(quadrature.size(), face_quadrature.size()),
                                             0.);
      static const PorousCoefficients open_water;

      const double theta = parameters.theta, dt = lengths.dt;
      const double w       = extrapolation_weight(lengths, theta);
      const double epsilon = parameters.interface_thickness();
      const double kappa   = gamma * epsilon; // the diffusivity of the profile
      const bool   conservative
        = parameters.phase_field_model == PhaseFieldModel::conservative_allen_cahn;

      std::vector<dealii::Tensor<1, 2>>            u_n(n_q), u_old(n_q), grad_phi_n(n_q);
      std::vector<double>                          phi_n(n_q), div_n(n_q), div_old(n_q);
      std::vector<double>                          value(n_dofs), advect(n_dofs);
      std::vector<dealii::Tensor<1, 2>>            gradient(n_dofs);
      dealii::FullMatrix<double>                   local_matrix(n_dofs, n_dofs);
      dealii::Vector<double>                       local_rhs(n_dofs);
      std::vector<dealii::types::global_dof_index> indices(n_dofs);

      // Where each cell's values and entries sit (after grid changes, once).
      if (scatter.empty())
        scatter.reinit(phase.dof_handler(), phase.constraints(), matrix, rhs);
      if (phase_gather.empty())
        phase_gather.reinit(phase.dof_handler(), phase_old);
      if (flow_gather.empty())
        flow_gather.reinit(flow.dof_handler(), flow.values(0));
      if (!flow_gather.matches(flow.values(1)))
        throw std::logic_error("PhaseFieldSystem::assemble: vectors of different layouts");
      const unsigned int  n_flow_dofs = flow.finite_element().n_dofs_per_cell();
      std::vector<double> flow_dofs_n(n_flow_dofs), flow_dofs_old(n_flow_dofs), phase_dofs(n_dofs);
      std::vector<unsigned int> flow_component(n_flow_dofs);
      for (unsigned int i = 0; i < n_flow_dofs; ++i)
        flow_component[i] = flow.finite_element().system_to_component_index(i).first;

      matrix                   = 0.;
      rhs                      = 0.;
      unsigned int cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(phase.dof_handler(), [&](const auto &cell) {
        fv.reinit(cell);
        const auto flow_cell = flow.cell_on(cell);
        fv_flow.reinit(flow_cell);
        // The fields at the quadrature points, summed over the shape functions in the
        // order FEValues::get_function_values() sums them (the same numbers, bit for bit).
        flow_gather.get(cell_number, flow.values(0), flow_dofs_n.data());
        flow_gather.get(cell_number, flow.values(1), flow_dofs_old.data());
        phase_gather.get(cell_number, phase_old, phase_dofs.data());
        linear_algebra::evaluate_velocity(
          fv_flow, flow_component, flow_dofs_n, &u_n, nullptr, &div_n);
        linear_algebra::evaluate_velocity(
          fv_flow, flow_component, flow_dofs_old, &u_old, nullptr, &div_old);
        linear_algebra::evaluate_scalar(fv, phase_dofs, &phi_n, &grad_phi_n);
        const double h = cell->extent_in_direction(0);
        if (porous_values)
          porous_values->reinit(cell, cell_number, dt, no_viscosity);

        local_matrix = 0.;
        local_rhs    = 0.;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const dealii::Tensor<1, 2> u_bar = u_n[q] + w * (u_n[q] - u_old[q]);
            const double               speed = u_bar.norm();
            // The advection in divergence form, div(n u phi) = n u . grad phi + phi
            // div(n u): summed over the test functions it leaves only the flux through
            // the sides, so the water volume is kept whatever the discrete divergence of
            // the stabilized velocity. In the pores the mixture's divergence R (with the
            // solid's flux) multiplies phi, and the equation is weighted by the fluid
            // fraction n (see the class's documentation; n = 1, R = div u in open water).
            const PorousCoefficients &medium  = porous_values ? (*porous_values)[q] : open_water;
            const double              n       = medium.n;
            const double              div_bar = div_n[q] + w * (div_n[q] - div_old[q]);
            const double              mixture_divergence
              = porous_values ? n * div_bar + u_bar * medium.grad_n + medium.solid_divergence :
                                div_bar;
            // SUPG parameter of the interface equation (paper 002, Eq. 95).
            const double tau = 1.
                               / std::sqrt(4. / (dt * dt) + 4. * speed * speed / (h * h)
                                           + 16. * kappa * kappa / (h * h * h * h));
            const double JxW = fv.JxW(q);
            const double p   = phi_n[q];
            // The explicit sharpening: the flux gamma phi (1 - phi) n of the
            // conservative form, or the double-well reaction of Allen-Cahn.
            const double               gradient_norm = grad_phi_n[q].norm();
            const dealii::Tensor<1, 2> sharpening_flux
              = conservative && gradient_norm > 1e-8 / h ?
                  gamma * p * (1. - p) * grad_phi_n[q] / gradient_norm :
                  dealii::Tensor<1, 2>();
            const double reaction
              = conservative ? 0. : -gamma * p * (1. - p) * (1. - 2. * p) / epsilon;
            const double explicit_residual
              = n * p / dt - (1. - theta) * (n * (u_bar * grad_phi_n[q]) + p * mixture_divergence);

            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                value[i]    = fv.shape_value(i, q);
                gradient[i] = fv.shape_grad(i, q);
                advect[i]   = n * (u_bar * gradient[i]) + value[i] * mixture_divergence;
              }
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const double test = value[i] + tau * u_bar * gradient[i];
                for (unsigned int j = 0; j < n_dofs; ++j)
                  local_matrix(i, j) += (test * (n * value[j] / dt + theta * advect[j])
                                         + theta * n * kappa * gradient[i] * gradient[j])
                                        * JxW;
                local_rhs(i) += (test * explicit_residual
                                 - (1. - theta) * n * kappa * gradient[i] * grad_phi_n[q]
                                 + n * (gradient[i] * sharpening_flux) + n * value[i] * reaction)
                                * JxW;
              }
          }
        // The inflow sides, weakly and upwind: where the flow enters (u_bar . n < 0) the
        // term - u_bar . n (phi - phi_in) psi pulls phi to what enters. Summed over the
        // test functions it replaces the flux phi u_bar . n by phi_in u_bar . n there, so
        // the water that enters is exactly what the inflow prescribes.
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f)
              && parameters.boundaries[cell->face(f)->boundary_id()] == FlowBoundary::inflow)
            {
              fv_face.reinit(cell, f);
              fv_face_flow.reinit(flow_cell, f);
              fv_face_flow[velocity].get_function_values(flow.values(0), u_face_n);
              fv_face_flow[velocity].get_function_values(flow.values(1), u_face_old);
              fv_face.get_function_values(phase_old, phi_face_n);
              if (porous_values)
                porous_values->reinit_face(cell, f, dt, no_viscosity);
              for (unsigned int q = 0; q < fv_face.n_quadrature_points; ++q)
                {
                  const dealii::Tensor<1, 2> u_bar
                    = u_face_n[q] + w * (u_face_n[q] - u_face_old[q]);
                  // The water's flux n u . n (the pore velocity times the fluid fraction).
                  const double n        = porous_values ? porous_values->face(q).n : 1.;
                  const double entering = std::min(n * (u_bar * fv_face.normal_vector(q)), 0.);
                  const double phi_in
                    = parameters.boundaries.inflow_phase(fv_face.quadrature_point(q)[1], epsilon);
                  const double JxW = fv_face.JxW(q);
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      const double psi = fv_face.shape_value(i, q);
                      for (unsigned int j = 0; j < n_dofs; ++j)
                        local_matrix(i, j)
                          -= theta * entering * psi * fv_face.shape_value(j, q) * JxW;
                      local_rhs(i)
                        += entering * ((1. - theta) * phi_face_n[q] - phi_in) * psi * JxW;
                    }
                }
            }
        cell->get_dof_indices(indices);
        scatter.add(
          cell_number, local_matrix, local_rhs, indices, phase.constraints(), matrix, rhs);
        ++cell_number;
      });
      matrix.compress(dealii::VectorOperation::add);
      rhs.compress(dealii::VectorOperation::add);
    }



    SolveReport
    PhaseFieldSystem::step(const StepLengths &lengths, const double gamma)
    {
      dealii::Timer timer;
      phase_old = phase.values(0);
      assemble(lengths, gamma);
      const double assembly_time   = timer.wall_time();
      solution                     = phase.locally_owned_values(0);
      const double          target = parameters.linear_tolerance * rhs.l2_norm();
      dealii::SolverControl control(parameters.max_iterations, std::max(target, 1e-300));
      dealii::TrilinosWrappers::SolverGMRES gmres(control);
      if (!ilu)
        ilu = std::make_unique<linear_algebra::IncompleteLU>(0);
      ilu->factorize(matrix); // ILU(0) of this step's values; symbolic after grid changes
      try
        {
          gmres.solve(matrix, solution, rhs, *ilu);
        }
      catch (const dealii::SolverControl::NoConvergence &failure)
        {
          throw RunFailure("the phase field's linear solver (GMRES) did not converge: "
                           "residual "
                           + to_string(failure.last_residual) + " after "
                           + std::to_string(failure.last_step) + " iterations");
        }
      phase.locally_owned_values(0) = solution;
      phase.values_changed(0);
      outflow = compute_outflow(lengths);
      SolveReport report{control.last_step(), control.last_value()};
      report.assembly_time = assembly_time;
      report.solve_time    = timer.wall_time() - assembly_time;
      return report;
    }



    double
    PhaseFieldSystem::compute_outflow(const StepLengths &lengths) const
    {
      // The discrete equation summed over the test functions: the volume changes by
      // - dt times the flux u_bar . n phi^{n+theta} through the sides, phi_in on the
      // inflow sides where the flow enters (see assemble()). The same quadrature, so the
      // balance closes to the solver's tolerance.
      const dealii::QGauss<1>                  face_quadrature(gauss_points());
      const unsigned int                       n_q = face_quadrature.size();
      const dealii::FEValuesExtractors::Vector velocity(0);
      dealii::FEFaceValues<2>                  fv_face(phase.finite_element(),
                                      face_quadrature,
                                      dealii::update_values | dealii::update_quadrature_points
                                        | dealii::update_normal_vectors
                                        | dealii::update_JxW_values);
      dealii::FEFaceValues<2>                  fv_face_flow(flow.finite_element(),
                                           face_quadrature,
                                           dealii::update_values);
      std::vector<dealii::Tensor<1, 2>>        u_n(n_q), u_old(n_q);
      std::vector<double>                      phi_new(n_q), phi_old(n_q);
      const double theta = parameters.theta, w = extrapolation_weight(lengths, theta);
      const double epsilon = parameters.interface_thickness();
      double       flux    = 0.;
      std::unique_ptr<PorousMediumValues> porous_values;
      if (porous.active())
        porous_values = std::make_unique<PorousMediumValues>(grid,
                                                             porous,
                                                             dealii::QGauss<2>(gauss_points()),
                                                             face_quadrature);
      const std::vector<double> no_viscosity(n_q, 0.);
      grid::for_each_owned_cell_in_tree_order(phase.dof_handler(), [&](const auto &cell) {
        if (!cell->at_boundary())
          return;
        const auto flow_cell = flow.cell_on(cell);
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->at_boundary(f))
              continue;
            const FlowBoundary side = parameters.boundaries[cell->face(f)->boundary_id()];
            if (side != FlowBoundary::open && side != FlowBoundary::inflow)
              continue;
            fv_face.reinit(cell, f);
            fv_face_flow.reinit(flow_cell, f);
            fv_face_flow[velocity].get_function_values(flow.values(0), u_n);
            fv_face_flow[velocity].get_function_values(flow.values(1), u_old);
            fv_face.get_function_values(phase.values(0), phi_new);
            fv_face.get_function_values(phase_old, phi_old);
            if (porous_values)
              porous_values->reinit_face(cell, f, lengths.dt, no_viscosity);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                // The water's flux n u . n (the pore velocity times the fluid fraction).
                const double n = porous_values ? porous_values->face(q).n : 1.;
                const double un
                  = n * ((u_n[q] + w * (u_n[q] - u_old[q])) * fv_face.normal_vector(q));
                const double phi = theta * phi_new[q] + (1. - theta) * phi_old[q];
                const double carried
                  = side == FlowBoundary::inflow && un < 0. ?
                      parameters.boundaries.inflow_phase(fv_face.quadrature_point(q)[1], epsilon) :
                      phi;
                flux += un * carried * fv_face.JxW(q);
              }
          }
      });
      return lengths.dt * dealii::Utilities::MPI::sum(flux, grid.communicator());
    }



    double
    PhaseFieldSystem::water_volume() const
    {
      if (!porous.active())
        return phase.integral();
      // The integral of n phi with the quadrature of the assembly, whose mass term summed
      // over the test functions is this integral (so the balance closes).
      const dealii::QGauss<2>   quadrature(gauss_points());
      const dealii::QGauss<1>   face_quadrature(gauss_points());
      dealii::FEValues<2>       fv(phase.finite_element(),
                             quadrature,
                             dealii::update_values | dealii::update_JxW_values);
      PorousMediumValues        porous_values(grid, porous, quadrature, face_quadrature);
      const std::vector<double> no_viscosity(quadrature.size(), 0.);
      std::vector<double>       phi(quadrature.size());
      double                    sum = 0.;
      grid::for_each_owned_cell_in_tree_order(phase.dof_handler(), [&](const auto &cell) {
        fv.reinit(cell);
        fv.get_function_values(phase.values(0), phi);
        porous_values.reinit(cell, 0., no_viscosity);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          sum += porous_values[q].n * phi[q] * fv.JxW(q);
      });
      return dealii::Utilities::MPI::sum(sum, grid.communicator());
    }
  } // namespace fluid
} // namespace slidewave
