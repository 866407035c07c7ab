#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/vector.h>
#include <slidewave/fluid/velocity_subscales.h>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_evaluation.h>
#include <stdexcept>

namespace slidewave
{
  namespace fluid
  {
    VelocitySubscales::VelocitySubscales(grid::BackgroundGrid &grid, const unsigned int degree)
      : field(grid,
              dealii::FESystem<2>(dealii::FE_DGQArbitraryNodes<2>(dealii::QGauss<1>(degree + 1)),
                                  2),
              1)
      , degree(degree)
      , n_q((degree + 1) * (degree + 1))
    {
      // The field's nodes are the flow's quadrature points, in the same order (both
      // tensor products with x running fastest): checked, not assumed.
      const dealii::QGauss<2> quadrature(degree + 1);
      const auto             &fe = field.finite_element();
      dof_component.resize(fe.n_dofs_per_cell());
      dof_point.resize(fe.n_dofs_per_cell());
      cell_indices.resize(fe.n_dofs_per_cell());
      const auto &support = fe.base_element(0).get_unit_support_points();
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto [component, point] = fe.system_to_component_index(i);
          dof_component[i]              = component;
          dof_point[i]                  = point;
          if (support[point].distance(quadrature.point(point)) > 1e-12)
            throw std::logic_error("VelocitySubscales: the field's nodes are not the flow's "
                                   "quadrature points");
        }
    }



    void
    VelocitySubscales::read_cell(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                                 std::vector<dealii::Tensor<1, 2>>                 &values) const
    {
      cell->get_dof_indices(cell_indices);
      const auto &u = field.values(0);
      for (unsigned int i = 0; i < cell_indices.size(); ++i)
        values[dof_point[i]][dof_component[i]] = u[cell_indices[i]];
    }



    void
    VelocitySubscales::begin_assembly(const unsigned int n_cells)
    {
      store.resize(static_cast<std::size_t>(n_cells) * n_q);
    }



    void
    VelocitySubscales::update(const grid::FiniteElementField   &flow,
                              const linear_algebra::CellGather &gather)
    {
      const auto             &fe = flow.finite_element();
      const dealii::QGauss<2> quadrature(degree + 1);
      dealii::FEValues<2>     fv(fe, quadrature, dealii::update_values | dealii::update_gradients);
      const unsigned int      n_dofs = fe.n_dofs_per_cell();
      std::vector<unsigned int> component(n_dofs);
      for (unsigned int i = 0; i < n_dofs; ++i)
        component[i] = fe.system_to_component_index(i).first;
      std::vector<double>               dofs(n_dofs);
      std::vector<dealii::Tensor<1, 2>> u(n_q), grad_p(n_q), subscale(n_q);
      std::vector<dealii::Tensor<2, 2>> grad_u(n_q);
      auto                             &owned       = field.locally_owned_values(0);
      unsigned int                      cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(flow.dof_handler(), [&](const auto &cell) {
        fv.reinit(cell);
        gather.get(cell_number, flow.values(0), dofs.data());
        linear_algebra::evaluate_velocity(fv, component, dofs, &u, &grad_u);
        std::fill(grad_p.begin(), grad_p.end(), dealii::Tensor<1, 2>());
        for (unsigned int i = 0; i < n_dofs; ++i)
          if (component[i] == 2)
            for (unsigned int q = 0; q < n_q; ++q)
              grad_p[q] += dofs[i] * fv.shape_grad(i, q);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Terms               &t = store[cell_number * n_q + q];
            const dealii::Tensor<1, 2> residual
              = t.mass * u[q] + grad_u[q] * t.advection + t.pressure_factor * grad_p[q] - t.known;
            subscale[q] = -t.tau_over_rho * residual;
          }
        field.cell_on(cell)->get_dof_indices(cell_indices);
        for (unsigned int i = 0; i < cell_indices.size(); ++i)
          owned[cell_indices[i]] = subscale[dof_point[i]][dof_component[i]];
        ++cell_number;
      });
      owned.compress(dealii::VectorOperation::insert);
      field.values_changed(0);
    }
  } // namespace fluid
} // namespace slidewave
