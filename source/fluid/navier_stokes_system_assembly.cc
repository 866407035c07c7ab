#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <memory>
#include <slidewave/fluid/navier_stokes_system.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_evaluation.h>
#include <stdexcept>

// NavierStokesSystem, its assembly: the discrete momentum and continuity equations of one
// step on every owned cell (the theta-scheme, SUPG, PSPG and grad-div stabilization, the
// porous solid's terms) and the open sides' share. The constraints, the set-up, the
// solve and the rest of the class are in navier_stokes_system.cc.
namespace slidewave
{
  namespace fluid
  {
    void
    NavierStokesSystem::assemble(const VectorType &phase_old, const StepLengths &lengths)
    {
      const auto             &fe     = flow.finite_element();
      const unsigned int      degree = fe.degree; // of the velocity and the pressure
      const dealii::QGauss<2> quadrature(degree + 1);
      const unsigned int      n_q = quadrature.size(), n_dofs = fe.n_dofs_per_cell();
      dealii::FEValues<2>     fv(fe,
                             quadrature,
                             dealii::update_values | dealii::update_gradients
                               | dealii::update_JxW_values);
      dealii::FEValues<2>     fv_phase(phase.finite_element(), quadrature, dealii::update_values);
      const dealii::QGauss<1> face_quadrature(degree + 1);
      dealii::FEFaceValues<2> fv_face(fe,
                                      face_quadrature,
                                      dealii::update_values | dealii::update_gradients
                                        | dealii::update_normal_vectors
                                        | dealii::update_JxW_values);
      dealii::FEFaceValues<2> fv_face_phase(phase.finite_element(),
                                            face_quadrature,
                                            dealii::update_values);
      const dealii::FEValuesExtractors::Vector velocity(0);
      const dealii::FEValuesExtractors::Scalar pressure(2);

      const double theta = parameters.theta, dt = lengths.dt;
      const double own_dt = std::max(lengths.own_dt, dt);
      const double w      = extrapolation_weight(lengths, theta);
      const auto  &fluid  = parameters.fluid;

      std::vector<dealii::Tensor<1, 2>> u_n(n_q), u_old(n_q);
      std::vector<dealii::Tensor<2, 2>> grad_u_n(n_q);
      std::vector<double>               phi_new(n_q), phi_old(n_q);
      std::vector<double>               value(n_dofs), advect(n_dofs);
      std::vector<dealii::Tensor<1, 2>> gradient(n_dofs);
      std::vector<unsigned int>         component(n_dofs), vertex(n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          vertex[i]    = fe.system_to_component_index(i).second;
        }
      dealii::FullMatrix<double>                   local_matrix(n_dofs, n_dofs);
      dealii::Vector<double>                       local_rhs(n_dofs);
      std::vector<dealii::types::global_dof_index> indices(n_dofs);

      // The porous solid's coefficients at the quadrature points (only when there is one).
      std::unique_ptr<PorousMediumValues> porous_values;
      if (porous.active())
        porous_values = std::make_unique<PorousMediumValues>(
          grid, porous, quadrature, face_quadrature, &porous_gathers);
      std::vector<double>               mu_q(n_q);
      std::vector<dealii::Tensor<1, 2>> subscale_n(n_q);
      if (subscales)
        subscales->begin_assembly(grid.triangulation().n_locally_owned_active_cells());

      // Where each cell's values and entries sit (after grid changes, once).
      if (scatter.empty())
        scatter.reinit(flow.dof_handler(), flow_constraints, matrix, rhs);
      if (flow_gather.empty())
        flow_gather.reinit(flow.dof_handler(), flow.values(0));
      if (phase_gather.empty())
        phase_gather.reinit(phase.dof_handler(), phase.values(0));
      if (!flow_gather.matches(flow.values(1)) || !phase_gather.matches(phase_old))
        throw std::logic_error("NavierStokesSystem::assemble: vectors of different layouts");
      const unsigned int  n_phase_dofs = phase.finite_element().n_dofs_per_cell();
      std::vector<double> dofs_n(n_dofs), dofs_old(n_dofs), phase_dofs_new(n_phase_dofs),
        phase_dofs_old(n_phase_dofs);

      // The grains' nodal coupling (NodalGrainsCoupling): the preconditioner's matrix, the
      // pointwise elimination, into `matrix`, and A_w = that minus the terms the coupling
      // replaces (nodal_delta) into coupled_matrix.
      NodalGrainsCoupling *const nodal = grains_coupling.get();
      dealii::FullMatrix<double> nodal_delta(nodal != nullptr ? n_dofs : 0,
                                             nodal != nullptr ? n_dofs : 0);
      dealii::Vector<double>            nodal_delta_rhs(nodal != nullptr ? n_dofs : 0);
      std::vector<double>               nodal_drag(n_q);
      std::vector<dealii::Tensor<1, 2>> nodal_v_s(n_q);
      if (nodal != nullptr)
        {
          // (the grains' nodes are the Q1 vertices; the scene refuses Q2 with them)
          if (n_dofs != 12)
            throw std::logic_error(
              "NavierStokesSystem::assemble: the grains' nodal coupling needs the Q1 element");
          if (!coupled_matrix_ready)
            {
              coupled_matrix.reinit(matrix); // the same sparsity: the scatter's positions
              coupled_matrix_ready = true;
            }
          coupled_matrix = 0.;
          nodal->begin(*porous.nodal_grains, dt);
        }
      matrix                   = 0.;
      rhs                      = 0.;
      unsigned int cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
        fv.reinit(cell);
        const auto phase_cell = phase.cell_on(cell);
        fv_phase.reinit(phase_cell);
        // The fields at the quadrature points, summed over the shape functions in the
        // order FEValues::get_function_values() sums them (the same numbers, bit for bit).
        flow_gather.get(cell_number, flow.values(0), dofs_n.data());
        flow_gather.get(cell_number, flow.values(1), dofs_old.data());
        phase_gather.get(cell_number, phase.values(0), phase_dofs_new.data());
        phase_gather.get(cell_number, phase_old, phase_dofs_old.data());
        linear_algebra::evaluate_velocity(fv, component, dofs_n, &u_n, &grad_u_n);
        linear_algebra::evaluate_velocity(fv, component, dofs_old, &u_old);
        linear_algebra::evaluate_scalar(fv_phase, phase_dofs_new, &phi_new);
        linear_algebra::evaluate_scalar(fv_phase, phase_dofs_old, &phi_old);
        // The length of the stabilization parameters: the nodes' spacing.
        const double h = cell->extent_in_direction(0) / degree;
        for (unsigned int q = 0; q < n_q; ++q)
          mu_q[q] = fluid.viscosity(theta * phi_new[q] + (1. - theta) * phi_old[q]);
        if (porous.active())
          porous_values->reinit(cell, cell_number, dt, mu_q);
        static const PorousCoefficients open_water;
        if (subscales)
          subscales->read(cell, subscale_n);

        local_matrix = 0.;
        local_rhs    = 0.;
        if (nodal != nullptr)
          {
            nodal_delta     = 0.;
            nodal_delta_rhs = 0.;
          }
        bool with_grains = false;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double phi = theta * phi_new[q] + (1. - theta) * phi_old[q];
            const double rho = fluid.density(phi), mu = fluid.viscosity(phi);
            const double nu = mu / rho;
            // The porous solid: fluid fraction n, its gradient, the drag C, the solid's
            // velocity and the shares of its momentum eliminated (PorousMedium; n = 1 and
            // zeros in open water: every term below is then the open water's, bit for bit).
            const PorousCoefficients   &medium = porous.active() ? (*porous_values)[q] : open_water;
            const double                n      = medium.n;
            const dealii::Tensor<1, 2> &grad_n = medium.grad_n;
            const double                drag   = medium.drag;
            const dealii::Tensor<1, 2> &v_s    = medium.v_s;
            // The water's pressure gradient and the solid's share it carries, over n (the
            // momentum residual's factor of grad p).
            const double pressure_factor = 1. + medium.pressure_share / n;
            // grad p^n: the skeleton's predicted velocity holds the old pressure's force,
            // so its eliminated share acts with the increment p - p^n (PorousMedium).
            dealii::Tensor<1, 2> grad_p_n;
            if (medium.pressure_share != 0. || medium.pressure_diffusion != 0.)
              for (unsigned int i = 0; i < n_dofs; ++i)
                if (component[i] == 2)
                  grad_p_n += dofs_n[i] * fv.shape_grad(i, q);
            const dealii::Tensor<1, 2> u_bar = u_n[q] + w * (u_n[q] - u_old[q]);
            const double               speed = u_bar.norm();
            // Tezduyar's parameters (paper 002, Eqs. 28-29): tau_m from the time step,
            // the advection, the viscosity and the drag; tau_cont from the element
            // Reynolds number. With dynamic subscales, tau_t from the subscale's own
            // time scale tau_s (the same without the step) and theta dt
            // (VelocitySubscales).
            const double advection_rate = 4. * speed * speed / (h * h);
            const double viscous_rate   = 16. * nu * nu / (h * h * h * h);
            const double drag_rate      = drag * drag / (n * n * rho * rho);
            const double tau_m
              = subscales ?
                  1.
                    / (1. / (theta * dt)
                       + std::sqrt(4. / (own_dt * own_dt) + advection_rate + viscous_rate
                                   + drag_rate)) :
                  1. / std::sqrt(4. / (dt * dt) + advection_rate + viscous_rate + drag_rate);
            const double reynolds = speed * h / (2. * nu);
            const double tau_cont
              = parameters.grad_div ? 0.5 * h * speed * std::min(reynolds / 3., 1.) : 0.;
            const double JxW = fv.JxW(q);
            if (nodal != nullptr)
              {
                nodal_drag[q] = medium.drag_coefficient;
                nodal_v_s[q]  = v_s;
                with_grains   = with_grains || n < 1.;
              }

            // Every shape function of FESystem(Q1^2, Q1) lives in one component
            // (component[i]: 0, 1 velocity, 2 pressure) with the scalar value N_i and
            // gradient G_i: the vector and tensor products of the weak form reduce to
            // products of these (below, a = component[i], b = component[j]).
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                value[i]    = fv.shape_value(i, q);
                gradient[i] = fv.shape_grad(i, q);
                advect[i]   = u_bar * gradient[i];
              }
            if (nodal != nullptr)
              add_nodal_delta(
                medium, grad_p_n, value, gradient, component, JxW, nodal_delta, nodal_delta_rhs);
            // The explicit part of the momentum residual: rho u^n / dt minus the
            // (1 - theta) share of the advection, plus gravity.
            const dealii::Tensor<1, 2> advect_n = grad_u_n[q] * u_bar;
            const dealii::Tensor<2, 2> sym_grad_n
              = 0.5 * (grad_u_n[q] + dealii::transpose(grad_u_n[q]));
            const dealii::Tensor<1, 2> explicit_residual
              = rho * u_n[q] / dt - (1. - theta) * rho * advect_n + rho * fluid.gravity
                + (drag / n) * v_s + (medium.pressure_share / n) * grad_p_n;
            // The implicit momentum residual of a velocity shape function (along its
            // component): (rho / dt + drag / n) N_j + theta rho u_bar . G_j.
            const double mass = rho / dt + drag / n;
            // The stabilization's known residual: with dynamic subscales, the old
            // subscale's share rho u'^n / (theta dt) as well.
            dealii::Tensor<1, 2> stabilized_known = explicit_residual;
            if (subscales)
              {
                stabilized_known += rho / (theta * dt) * subscale_n[q];
                subscales->record(
                  cell_number,
                  q,
                  {mass, pressure_factor, tau_m / rho, theta * rho * u_bar, stabilized_known});
              }

            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const unsigned int          a  = component[i];
                const double                Ni = value[i];
                const dealii::Tensor<1, 2> &Gi = gradient[i];
                // SUPG and PSPG share the residual: the test function n tau_m (u_bar .
                // grad) w + n tau_m / rho grad q.
                if (a < 2)
                  {
                    const double supg = n * tau_m * advect[i];
                    for (unsigned int j = 0; j < n_dofs; ++j)
                      {
                        const unsigned int          b  = component[j];
                        const double                Nj = value[j];
                        const dealii::Tensor<1, 2> &Gj = gradient[j];
                        double                      m  = 0.;
                        if (b < 2)
                          {
                            // viscosity 2 mu eps(w) : eps(u) and grad-div
                            m = n * theta * mu * Gi[b] * Gj[a] + n * tau_cont * rho * Gi[a] * Gj[b];
                            if (a == b)
                              {
                                const double residual = mass * Nj + theta * rho * advect[j];
                                m += n * (rho / dt) * Ni * Nj + n * theta * rho * Ni * advect[j]
                                     + n * theta * mu * (Gi * Gj) + drag * Ni * Nj
                                     + supg * residual;
                              }
                          }
                        else // pressure: - (n div w + w . grad n) p, the solid's share
                             // s (1 - n) w . grad p and SUPG of grad p
                          m = -(n * Gi[a] + Ni * grad_n[a]) * Nj
                              + medium.pressure_share * Ni * Gj[a] + supg * pressure_factor * Gj[a];
                        local_matrix(i, j) += m * JxW;
                      }
                    local_rhs(i) += (n * Ni * explicit_residual[a]
                                     - n * (1. - theta) * 2. * mu * (Gi * sym_grad_n[a])
                                     + supg * stabilized_known[a])
                                    * JxW;
                  }
                else
                  {
                    const double pspg = n * tau_m / rho;
                    for (unsigned int j = 0; j < n_dofs; ++j)
                      {
                        const unsigned int          b  = component[j];
                        const double                Nj = value[j];
                        const dealii::Tensor<1, 2> &Gj = gradient[j];
                        // continuity q (n div u + u . grad n) - s (1 - n) grad q . u,
                        // the Darcy flow's (1 - n)^2 Delta grad q . grad p, and PSPG
                        const double m
                          = b < 2 ?
                              Ni * (n * Gj[b] + Nj * grad_n[b]) - medium.pressure_share * Gi[b] * Nj
                                + pspg * Gi[b] * (mass * Nj + theta * rho * advect[j]) :
                              (pspg * pressure_factor + medium.pressure_diffusion) * (Gi * Gj);
                        local_matrix(i, j) += m * JxW;
                      }
                    local_rhs(i)
                      += (-Ni * medium.solid_divergence
                          + Gi * (medium.correction_flux + medium.pressure_diffusion * grad_p_n)
                          + pspg * (Gi * stabilized_known))
                         * JxW;
                  }
              }
          }
        add_open_boundary_terms(cell,
                                phase_cell,
                                fv_face,
                                fv_face_phase,
                                lengths,
                                porous_values.get(),
                                local_matrix,
                                local_rhs,
                                nodal != nullptr ? &nodal_delta : nullptr,
                                nodal != nullptr ? &nodal_delta_rhs : nullptr);
        cell->get_dof_indices(indices);
        if (nodal != nullptr)
          {
            scatter.add_matrix(cell_number, local_matrix, indices, flow_constraints, matrix);
            local_matrix.add(-1., nodal_delta);
            local_rhs.add(-1., nodal_delta_rhs);
            scatter.add(
              cell_number, local_matrix, local_rhs, indices, flow_constraints, coupled_matrix, rhs);
            if (with_grains)
              nodal->add_cell(
                cell_number,
                dealii::DoFHandler<2>::active_cell_iterator(
                  &cell->get_triangulation(), cell->level(), cell->index(), &grid.dof_handler()),
                fv,
                component,
                vertex,
                nodal_drag,
                nodal_v_s,
                porous_values->vertex_fluid_fraction(),
                indices);
          }
        else
          scatter.add(cell_number, local_matrix, local_rhs, indices, flow_constraints, matrix, rhs);
        ++cell_number;
      });
      matrix.compress(dealii::VectorOperation::add);
      rhs.compress(dealii::VectorOperation::add);
      if (nodal != nullptr)
        {
          coupled_matrix.compress(dealii::VectorOperation::add);
          nodal->finish(flow_constraints, flow_gather, flow.values(0), rhs);
        }
    }



    void
    NavierStokesSystem::add_nodal_delta(const PorousCoefficients                &medium,
                                        const dealii::Tensor<1, 2>              &grad_p_n,
                                        const std::vector<double>               &value,
                                        const std::vector<dealii::Tensor<1, 2>> &gradient,
                                        const std::vector<unsigned int>         &component,
                                        const double                             JxW,
                                        dealii::FullMatrix<double>              &delta,
                                        dealii::Vector<double>                  &delta_rhs)
    {
      // The Galerkin terms of the pointwise elimination that the grains' nodal coupling
      // replaces: its drag C (1 - s) against C, the share s (1 - n) of the grains'
      // pressure gradient, the correction flux and the Darcy diffusion (PorousMedium).
      // The stabilization keeps the eliminated residual.
      const double extra_drag = medium.drag - medium.drag_coefficient;
      if (extra_drag == 0. && medium.pressure_share == 0. && medium.pressure_diffusion == 0.)
        return;
      const unsigned int n_dofs = value.size();
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int          a  = component[i];
          const double                Ni = value[i];
          const dealii::Tensor<1, 2> &Gi = gradient[i];
          if (a < 2)
            {
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  const unsigned int b = component[j];
                  const double       m = b == a ? extra_drag * Ni * value[j] :
                                         b == 2 ? medium.pressure_share * Ni * gradient[j][a] :
                                                  0.;
                  delta(i, j) += m * JxW;
                }
              delta_rhs(i)
                += Ni * (extra_drag * medium.v_s[a] + medium.pressure_share * grad_p_n[a]) * JxW;
            }
          else
            {
              for (unsigned int j = 0; j < n_dofs; ++j)
                {
                  const unsigned int b = component[j];
                  const double       m = b < 2 ? -medium.pressure_share * Gi[b] * value[j] :
                                                 medium.pressure_diffusion * (Gi * gradient[j]);
                  delta(i, j) += m * JxW;
                }
              delta_rhs(i)
                += Gi * (medium.correction_flux + medium.pressure_diffusion * grad_p_n) * JxW;
            }
        }
    }



    template <class FlowCell, class PhaseCell>
    void
    NavierStokesSystem::add_open_boundary_terms(const FlowCell             &cell,
                                                const PhaseCell            &phase_cell,
                                                dealii::FEFaceValues<2>    &fv_face,
                                                dealii::FEFaceValues<2>    &fv_face_phase,
                                                const StepLengths          &lengths,
                                                PorousMediumValues         *porous_values,
                                                dealii::FullMatrix<double> &local_matrix,
                                                dealii::Vector<double>     &local_rhs,
                                                dealii::FullMatrix<double> *nodal_delta,
                                                dealii::Vector<double>     *nodal_delta_rhs) const
    {
      // On an open side the symmetric viscous stress would hold the whole traction
      // (2 mu eps(u) - p I) n at zero, which a fully developed outflow (Poiseuille) does
      // not satisfy. The term - mu (grad u)^T n turns the natural condition into
      // (mu grad u - p I) n = 0: the pressure is the ambient 0 and the velocity leaves
      // without a normal gradient, as an outflow of water or air does. Where the flow
      // comes back in (u_bar . n < 0), the backflow term beta rho |u_bar . n| w . u
      // (implicit) takes out the kinetic energy that the inflow would otherwise bring
      // in unbounded (Esmaily Moghadam et al. 2011).
      //
      // Where a skeleton whose momentum the flow eliminates reaches an open side, the
      // continuity's weak divergence of the solid's correction flux has its flux through
      // the side, s (1 - n)(u - v*) - (1 - n)^2 Delta grad p (PorousMedium): the water
      // drained through the side relative to the grains.
      const dealii::FEValuesExtractors::Vector velocity(0);
      const dealii::FEValuesExtractors::Scalar pressure(2);
      const double                             theta = parameters.theta;
      const double                             beta  = parameters.boundaries.backflow;
      const double                             w     = extrapolation_weight(lengths, theta);
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->at_boundary(f)
              || parameters.boundaries[cell->face(f)->boundary_id()] != FlowBoundary::open)
            continue;
          fv_face.reinit(cell, f);
          fv_face_phase.reinit(phase_cell, f);
          const unsigned int                n_q = fv_face.n_quadrature_points;
          std::vector<double>               phi(n_q);
          std::vector<dealii::Tensor<2, 2>> grad_u_n(n_q);
          std::vector<dealii::Tensor<1, 2>> u_n(n_q), u_old(n_q);
          fv_face_phase.get_function_values(phase.values(0), phi);
          fv_face[velocity].get_function_gradients(flow.values(0), grad_u_n);
          fv_face[velocity].get_function_values(flow.values(0), u_n);
          fv_face[velocity].get_function_values(flow.values(1), u_old);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double                mu           = parameters.fluid.viscosity(phi[q]);
              const dealii::Tensor<1, 2> &normal       = fv_face.normal_vector(q);
              const double                JxW          = fv_face.JxW(q);
              const dealii::Tensor<1, 2>  old_traction = dealii::transpose(grad_u_n[q]) * normal;
              const double inflow   = std::min((u_n[q] + w * (u_n[q] - u_old[q])) * normal, 0.);
              const double backflow = beta * parameters.fluid.density(phi[q]) * (-inflow);
              for (unsigned int i = 0; i < local_rhs.size(); ++i)
                {
                  const dealii::Tensor<1, 2> test = fv_face[velocity].value(i, q);
                  if (test.norm_square() == 0.)
                    continue;
                  for (unsigned int j = 0; j < local_rhs.size(); ++j)
                    local_matrix(i, j)
                      += (backflow * test * fv_face[velocity].value(j, q)
                          - theta * mu * test
                              * (dealii::transpose(fv_face[velocity].gradient(j, q)) * normal))
                         * JxW;
                  local_rhs(i) += (1. - theta) * mu * test * old_traction * JxW;
                }
            }
          if (porous_values != nullptr && porous.grain_density > 0.)
            {
              std::vector<double> mu(n_q);
              for (unsigned int q = 0; q < n_q; ++q)
                mu[q] = parameters.fluid.viscosity(phi[q]);
              porous_values->reinit_face(cell, f, lengths.dt, mu);
              std::vector<dealii::Tensor<1, 2>> grad_p_n(n_q);
              fv_face[pressure].get_function_gradients(flow.values(0), grad_p_n);
              porous_values->add_open_side_flux(fv_face, grad_p_n, local_matrix, local_rhs);
              if (nodal_delta != nullptr)
                porous_values->add_open_side_flux(fv_face,
                                                  grad_p_n,
                                                  *nodal_delta,
                                                  *nodal_delta_rhs);
            }
        }
    }
  } // namespace fluid
} // namespace slidewave
