#include <algorithm>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <limits>
#include <slidewave/granular/coupling_point_values.h>
#include <slidewave/granular/drag_projection.h>
#include <slidewave/grid/tree_order.h>

namespace slidewave
{
  namespace granular
  {
    DragProjection::DragProjection(const grid::BackgroundGrid         &grid,
                                   const fluid::FreeSurfaceParameters &parameters,
                                   const double                        grain_density)
      : grid(grid)
      , parameters(parameters)
      , grain_density(grain_density)
    {
    }



    void
    DragProjection::assemble(const grid::FiniteElementField &flow,
                             const grid::FiniteElementField &phase,
                             const SkeletonFields           &fields,
                             const grid::NodalWorkspace     &nodes,
                             const double                    dt)
    {
      // The water's quadrature (Q1: 2 x 2 Gauss points), fields and coefficients.
      CouplingPointValues        values(grid, parameters, flow, phase, fields, gathers, true);
      const dealii::FEValues<2> &fv_grid = values.grid_values();
      std::vector<dealii::types::global_dof_index> indices(fv_grid.dofs_per_cell);
      AssertDimension(indices.size(), 4);
      std::vector<grid::NodalCellOperator::CellMatrix> &cells = projection.cells;
      cells.clear();
      for (unsigned int d = 0; d < 2; ++d)
        rhs[d] = 0.;
      // (in the tree's order: the conjugate gradients' sums repeat in a resumed run)
      unsigned int cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(grid.dof_handler(), [&](const auto &cell) {
        if (!values.reinit(cell, cell_number++))
          return;
        cell->get_dof_indices(indices);
        grid::NodalCellOperator::CellMatrix block;
        for (unsigned int i = 0; i < 4; ++i)
          block.nodes[i] = nodes.local_index(indices[i]);
        block.matrix.fill(0.);
        double w_min = std::numeric_limits<double>::max(), w_max = 0.;
        for (unsigned int q = 0; q < values.n_points(); ++q)
          {
            const double solid  = 1. - values.n[q];
            const double C      = values.drag[q];
            const double weight = (grain_density * solid / dt + C) * fv_grid.JxW(q);
            w_min               = std::min(w_min, weight);
            w_max               = std::max(w_max, weight);
            // The predicted velocity, from its flux as the water read it.
            const dealii::Tensor<1, 2> load = (C * (values.u[q] - values.v_s[q])
                                               - solid * (values.grad_p[q] - values.grad_p_old[q]))
                                              * fv_grid.JxW(q);
            for (unsigned int i = 0; i < 4; ++i)
              {
                const double Ni = fv_grid.shape_value(i, q);
                for (unsigned int d = 0; d < 2; ++d)
                  rhs[d].local_element(block.nodes[i]) += load[d] * Ni;
                for (unsigned int j = 0; j < 4; ++j)
                  block.matrix[4 * i + j] += weight * Ni * fv_grid.shape_value(j, q);
              }
          }
        // Where the weight varies across the cell (the mass's edge, where the grains
        // thin out) the consistent matrix extrapolates: a node of the cell's light
        // corner takes many times its heavy neighbour's increment, of opposite sign.
        // There the cell's matrix is lumped in proportion to the weight's variation,
        // 1 - w_min / w_max (its row sums, and so the momentum, unchanged); a cell
        // of uniform weight (inside the mass) keeps the consistent one.
        const double lumping = w_max > 0. ? 1. - w_min / w_max : 0.;
        if (lumping > 0.)
          for (unsigned int i = 0; i < 4; ++i)
            {
              double row = 0.;
              for (unsigned int j = 0; j < 4; ++j)
                {
                  row += block.matrix[4 * i + j];
                  block.matrix[4 * i + j] *= 1. - lumping;
                }
              block.matrix[4 * i + i] += lumping * row;
            }
        cells.push_back(block);
      });
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(rhs[d]);
          rhs[d].compress(dealii::VectorOperation::add);
        }
    }



    void
    DragProjection::increment(const grid::FiniteElementField  &flow,
                              const grid::FiniteElementField  &phase,
                              const SkeletonFields            &fields,
                              const grid::NodalWorkspace      &nodes,
                              const grid::VelocityConstraints &constraints,
                              const double                     dt,
                              std::array<Vector, 2>           &increment)
    {
      if (sums.get_partitioner() != nodes.nodal_mass.get_partitioner())
        {
          for (Vector *v : {&free[0], &free[1], &inverse_diagonal, &rhs[0], &rhs[1], &sums})
            v->reinit(nodes.nodal_mass);
          gathers.clear(); // the grid changed
        }
      projection.reinit(nodes, {{&free[0], &free[1]}});
      assemble(flow, phase, fields, nodes, dt);

      // The row sums (the lumped weighted mass): the preconditioner, and which nodes the
      // cells with grains reach.
      projection.row_sums(sums, inverse_diagonal);
      const unsigned int n_owned = sums.locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        free[0].local_element(i) = free[1].local_element(i) = 1.;
      constraints.apply(free[0], free[1]); // the held components
      for (const unsigned int i : nodes.hanging_nodes())
        if (i < n_owned)
          free[0].local_element(i) = free[1].local_element(i) = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double sum = sums.local_element(i);
          if (!(sum > 0.))
            free[0].local_element(i) = free[1].local_element(i) = 0.;
        }

      for (unsigned int d = 0; d < 2; ++d)
        {
          Vector &b = rhs[d];
          for (unsigned int i = 0; i < n_owned; ++i)
            b.local_element(i) *= free[d].local_element(i);
          Vector &x = increment[d];
          if (x.get_partitioner() != nodes.nodal_mass.get_partitioner())
            x.reinit(nodes.nodal_mass);
          projection.solve(d, x, b, inverse_diagonal, 1e-10, 200, "the skeleton's drag increment");
        }
    }
  } // namespace granular
} // namespace slidewave
