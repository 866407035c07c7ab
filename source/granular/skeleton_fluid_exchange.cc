#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <slidewave/granular/coupling_point_values.h>
#include <slidewave/granular/skeleton_fluid_exchange.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_evaluation.h>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** The smallest fluid fraction handed to the water (grains packed past 99 %). */
      constexpr double min_fluid_fraction = 0.01;

    } // namespace



    SkeletonFluidExchange::SkeletonFluidExchange(const grid::BackgroundGrid         &grid,
                                                 const fluid::FreeSurfaceParameters &parameters)
      : grid(grid)
      , parameters(parameters)
    {
    }



    void
    SkeletonFluidExchange::to_fluid(const grid::NodalWorkspace      &nodes,
                                    const grid::VelocityConstraints &constraints,
                                    const double                     empty_mass,
                                    const SkeletonFields            &fields,
                                    const double                     predictor_step,
                                    const grid::FiniteElementField  *flow)
    {
      using Vector = grid::NodalWorkspace::Vector;
      if (fraction.get_partitioner() != nodes.nodal_mass.get_partitioner())
        {
          for (Vector *v :
               {&fraction, &inverse_permeability, &vx, &vy, &pressure_work[0], &pressure_work[1]})
            v->reinit(nodes.nodal_mass);
          gathers.clear(); // the grid changed
        }
      const unsigned int n_owned = nodes.nodal_mass.locally_owned_size();
      const double       mu      = parameters.fluid.water_viscosity;
      const Vector      &solid   = nodes.fields[0];
      const Vector      &drag    = nodes.fields[1];
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double inverse_area = nodes.inverse_area[i];
          const double n
            = std::clamp(1. - solid.local_element(i) * inverse_area, min_fluid_fraction, 1.);
          fraction.local_element(i) = n;
          inverse_permeability.local_element(i)
            = drag.local_element(i) * inverse_area / (n * n * mu);
        }
      // On an adaptive grid the sums of a hanging node went to its parents: its values
      // come from theirs, as every Q1 field's there.
      for (Vector *v : {&fraction, &inverse_permeability})
        {
          v->update_ghost_values();
          nodes.interpolate_hanging_nodes(*v);
        }
      fields.fluid_fraction->copy_from_grid_nodes({&fraction});
      fields.inverse_permeability->copy_from_grid_nodes({&inverse_permeability});

      // The semi-implicit coupling's predictor holds the old pressure's force on the
      // grains, -(1 - n) grad p^n with this step's fluid fraction (fluid::PorousMedium).
      const bool with_pressure = flow != nullptr && predictor_step > 0.;
      if (with_pressure)
        pressure_force(*flow, fields, nodes, pressure_work);
      // The solid's flux of the velocity v^n + step (f + f_p) / m into the field @p field:
      // v^n (step 0), or v* (the semi-implicit predictor). The skeleton's sides and walls
      // hold its velocity: the water sees it held too. The water gets the flux (1 - n_I)
      // v_I = S_I v_I / A_I: a node with a tiny mass (which GIMP's gradients may give any
      // velocity) hands over a tiny flux.
      const auto flux_into = [&](const double step, grid::FiniteElementField &field) {
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double m = nodes.nodal_mass.local_element(i);
            if (m > empty_mass)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  double f = nodes.force[d].local_element(i);
                  if (with_pressure)
                    f += pressure_work[d].local_element(i);
                  (d == 0 ? vx : vy).local_element(i)
                    = (nodes.momentum[d].local_element(i) + step * f) / m;
                }
            else
              vx.local_element(i) = vy.local_element(i) = 0.;
          }
        constraints.apply(vx, vy);
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double solid = 1. - fraction.local_element(i);
            vx.local_element(i) *= solid;
            vy.local_element(i) *= solid;
          }
        for (Vector *v : {&vx, &vy})
          {
            v->update_ghost_values();
            nodes.interpolate_hanging_nodes(*v);
          }
        field.copy_from_grid_nodes({&vx, &vy});
      };
      // The phase field's flux of v^n first (when it has its own), then the flow's.
      if (fields.start_flux != nullptr)
        flux_into(0., *fields.start_flux);
      flux_into(predictor_step, *fields.solid_flux);
    }



    void
    SkeletonFluidExchange::pressure_force(const grid::FiniteElementField              &flow,
                                          const SkeletonFields                        &fields,
                                          const grid::NodalWorkspace                  &nodes,
                                          std::array<grid::NodalWorkspace::Vector, 2> &force)
    {
      const dealii::QGauss<2> quadrature(flow.finite_element().degree + 1);
      const unsigned int      n_q = quadrature.size();
      dealii::FEValues<2>     fv_flow(flow.finite_element(), quadrature, dealii::update_gradients);
      dealii::FEValues<2>     fv_scalar(fields.fluid_fraction->finite_element(),
                                    quadrature,
                                    dealii::update_values);
      dealii::FEValues<2>     fv_grid(grid.dof_handler().get_fe(),
                                  quadrature,
                                  dealii::update_values | dealii::update_JxW_values);
      std::vector<dealii::Tensor<1, 2>>            grad_p(n_q);
      std::vector<double>                          n(n_q);
      std::vector<dealii::types::global_dof_index> indices(fv_grid.dofs_per_cell);
      // The cells' values read by the gathers, summed as FEValues sums them.
      gathers.prepare(fields.fluid_fraction, nullptr, nullptr, &flow, nullptr);
      const auto               &fe_flow = flow.finite_element();
      std::vector<double>       dofs_n(fields.fluid_fraction->finite_element().n_dofs_per_cell());
      std::vector<double>       dofs_flow(fe_flow.n_dofs_per_cell());
      std::vector<unsigned int> local(indices.size()), component;
      for (unsigned int i = 0; i < fe_flow.n_dofs_per_cell(); ++i)
        component.push_back(fe_flow.system_to_component_index(i).first);
      for (unsigned int d = 0; d < 2; ++d)
        force[d] = 0.;
      // (in the tree's order, as every sum into the nodes: a resumed run repeats it)
      unsigned int cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(grid.dof_handler(), [&](const auto &cell) {
        const unsigned int number = cell_number++;
        fv_scalar.reinit(fields.fluid_fraction->cell_on(cell));
        gathers.fraction.get(number, fields.fluid_fraction->values(0), dofs_n.data());
        linear_algebra::evaluate_scalar(fv_scalar, dofs_n, &n);
        if (*std::min_element(n.begin(), n.end()) >= 1.)
          return; // no grains in the cell
        fv_flow.reinit(flow.cell_on(cell));
        gathers.flow.get(number, flow.values(0), dofs_flow.data());
        linear_algebra::evaluate_component_gradient(fv_flow, component, dofs_flow, 2, grad_p);
        fv_grid.reinit(cell);
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          local[i] = nodes.local_index(indices[i]);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const dealii::Tensor<1, 2> traction = -grad_p[q] * fv_grid.JxW(q);
            for (unsigned int i = 0; i < indices.size(); ++i)
              for (unsigned int d = 0; d < 2; ++d)
                force[d].local_element(local[i]) += traction[d] * fv_grid.shape_value(i, q);
          }
      });
      lump_on_grains(nodes, force);
    }



    void
    SkeletonFluidExchange::lump_on_grains(const grid::NodalWorkspace                  &nodes,
                                          std::array<grid::NodalWorkspace::Vector, 2> &force) const
    {
      // The node's own solid fraction 1 - n_I = S_I / A_I: the force is that on the node's
      // grains, so that a node the grains barely touch (a tiny mass) gets a tiny force and
      // an acceleration -grad p / rho^s like any other.
      const unsigned int n_owned = fraction.locally_owned_size();
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(force[d]);
          force[d].compress(dealii::VectorOperation::add);
          for (unsigned int i = 0; i < n_owned; ++i)
            force[d].local_element(i) *= 1. - fraction.local_element(i);
        }
    }



    void
    SkeletonFluidExchange::to_skeleton(const grid::FiniteElementField              &flow,
                                       const grid::FiniteElementField              &phase,
                                       const SkeletonFields                        &fields,
                                       const grid::NodalWorkspace                  &nodes,
                                       std::array<grid::NodalWorkspace::Vector, 2> &force,
                                       grid::NodalWorkspace::Vector                *water_drag)
    {
      // The same quadrature, fields and coefficients as the water's assembly.
      CouplingPointValues        values(grid, parameters, flow, phase, fields, gathers);
      const dealii::FEValues<2> &fv_grid = values.grid_values();
      std::vector<dealii::types::global_dof_index> indices(fv_grid.dofs_per_cell);
      std::vector<unsigned int>                    local(indices.size());
      for (unsigned int d = 0; d < 2; ++d)
        force[d] = pressure_work[d] = 0.;
      if (water_drag != nullptr)
        *water_drag = 0.;
      // Semi-implicit: the drag on the grains' side is - C v_s of the new step, which the
      // nodes take implicitly with W_I (PorousSkeletonModel::update_nodal_velocity).
      const double explicit_drag = water_drag != nullptr ? 0. : 1.;
      unsigned int cell_number   = 0;
      grid::for_each_owned_cell_in_tree_order(grid.dof_handler(), [&](const auto &cell) {
        if (!values.reinit(cell, cell_number++))
          return;
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          local[i] = nodes.local_index(indices[i]);
        for (unsigned int q = 0; q < values.n_points(); ++q)
          {
            const double               C = values.drag[q];
            const dealii::Tensor<1, 2> traction
              = C * (values.u[q] - explicit_drag * values.v_s[q]) * fv_grid.JxW(q);
            // (the pressure's share, -integral N_I grad p, lumped on the grains below)
            const dealii::Tensor<1, 2> pressure_traction = -values.grad_p[q] * fv_grid.JxW(q);
            for (unsigned int i = 0; i < indices.size(); ++i)
              for (unsigned int d = 0; d < 2; ++d)
                {
                  force[d].local_element(local[i]) += traction[d] * fv_grid.shape_value(i, q);
                  pressure_work[d].local_element(local[i])
                    += pressure_traction[d] * fv_grid.shape_value(i, q);
                }
            if (water_drag != nullptr)
              for (unsigned int i = 0; i < indices.size(); ++i)
                water_drag->local_element(local[i])
                  += C * fv_grid.JxW(q) * fv_grid.shape_value(i, q);
          }
      });
      // What landed on a hanging node belongs to its parents (the transpose of the
      // interpolation, as the points' scatter): no force is lost where cells change size.
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(force[d]);
          force[d].compress(dealii::VectorOperation::add);
        }
      if (water_drag != nullptr)
        {
          nodes.condense_hanging_nodes(*water_drag);
          water_drag->compress(dealii::VectorOperation::add);
        }
      // The pressure's force on the grains, lumped at the nodes (as pressure_force()).
      lump_on_grains(nodes, pressure_work);
      for (unsigned int d = 0; d < 2; ++d)
        force[d] += pressure_work[d];
    }



    void
    SkeletonFluidExchange::relative_speed(const grid::FiniteElementField &flow,
                                          const SkeletonFields           &fields,
                                          const grid::NodalWorkspace     &nodes,
                                          grid::NodalWorkspace::Vector   &speed) const
    {
      grid::NodalWorkspace::Vector all(nodes.nodal_mass);
      const auto                  &u   = flow.values(0);
      const auto                  &v_s = fields.solid_flux->values(0);
      for (const auto &cell : grid.dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const auto flow_cell  = flow.cell_on(cell);
            const auto solid_cell = fields.solid_flux->cell_on(cell);
            for (const unsigned int v : cell->vertex_indices())
              {
                const auto node = cell->vertex_dof_index(v, 0);
                if (!all.in_local_range(node))
                  continue;
                // The vertex's dofs of FESystem(Q1^2, Q1) and of Q1^2, by component.
                // The solid's velocity from its flux (1 - n_I) v_I.
                const double solid = 1. - fraction(node);
                double       w2    = 0.;
                for (unsigned int d = 0; d < 2; ++d)
                  {
                    const double w
                      = u[flow_cell->vertex_dof_index(v, d)]
                        - (solid > 0. ? v_s[solid_cell->vertex_dof_index(v, d)] / solid : 0.);
                    w2 += w * w;
                  }
                all(node) = std::sqrt(w2);
              }
          }
      // Only this step's nodes: the others must stay zero for the next scatter.
      const unsigned int n_owned = nodes.nodal_mass.locally_owned_size();
      for (const unsigned int i : nodes.active())
        if (i < n_owned)
          speed.local_element(i) = all.local_element(i);
      speed.update_ghost_values();
    }
  } // namespace granular
} // namespace slidewave
