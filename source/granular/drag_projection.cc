#include <algorithm>
#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/granular/coupling_point_values.h>
#include <slidewave/granular/drag_projection.h>
#include <slidewave/grid/tree_order.h>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** One component's operator, as the conjugate gradients call it. */
      struct ComponentOperator
      {
        const DragProjection &projection;
        unsigned int          d;
        void
        vmult(DragProjection::Vector &y, const DragProjection::Vector &x) const
        {
          projection.vmult(d, y, x);
        }
      };

      /** Jacobi: the inverse row sums. */
      struct InverseDiagonal
      {
        const DragProjection::Vector &inverse;
        void
        vmult(DragProjection::Vector &y, const DragProjection::Vector &x) const
        {
          for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
            y.local_element(i) = inverse.local_element(i) * x.local_element(i);
        }
      };
    } // namespace



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
      cells.clear();
      for (unsigned int d = 0; d < 2; ++d)
        rhs[d] = 0.;
      // (in the tree's order: the conjugate gradients' sums repeat in a resumed run)
      unsigned int cell_number = 0;
      grid::for_each_owned_cell_in_tree_order(grid.dof_handler(), [&](const auto &cell) {
        if (!values.reinit(cell, cell_number++))
          return;
        cell->get_dof_indices(indices);
        CellMatrix block;
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
    DragProjection::vmult(const unsigned int d, Vector &y, const Vector &x) const
    {
      const grid::NodalWorkspace &nodes   = *workspace;
      const unsigned int          n_owned = x.locally_owned_size();
      // x on the free nodes, the hanging ones from their parents.
      for (unsigned int i = 0; i < n_owned; ++i)
        work.local_element(i) = free[d].local_element(i) * x.local_element(i);
      work.update_ghost_values();
      nodes.interpolate_hanging_nodes(work);
      product = 0.;
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          {
            double sum = 0.;
            for (unsigned int j = 0; j < 4; ++j)
              sum += cell.matrix[4 * i + j] * work.local_element(cell.nodes[j]);
            product.local_element(cell.nodes[i]) += sum;
          }
      nodes.condense_hanging_nodes(product);
      product.compress(dealii::VectorOperation::add);
      work.zero_out_ghost_values();
      // The identity on the held, hanging and empty nodes: symmetric, positive definite.
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double f     = free[d].local_element(i);
          y.local_element(i) = f * product.local_element(i) + (1. - f) * x.local_element(i);
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
      workspace = &nodes;
      if (work.get_partitioner() != nodes.nodal_mass.get_partitioner())
        {
          for (Vector *v :
               {&free[0], &free[1], &inverse_diagonal, &rhs[0], &rhs[1], &work, &product})
            v->reinit(nodes.nodal_mass);
          gathers.clear(); // the grid changed
        }
      assemble(flow, phase, fields, nodes, dt);

      // The row sums (the lumped weighted mass): the preconditioner, and which nodes the
      // cells with grains reach.
      product = 0.;
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            product.local_element(cell.nodes[i]) += cell.matrix[4 * i + j];
      nodes.condense_hanging_nodes(product);
      product.compress(dealii::VectorOperation::add);
      const unsigned int n_owned = product.locally_owned_size();
      for (unsigned int i = 0; i < n_owned; ++i)
        free[0].local_element(i) = free[1].local_element(i) = 1.;
      constraints.apply(free[0], free[1]); // the held components
      for (const unsigned int i : nodes.hanging_nodes())
        if (i < n_owned)
          free[0].local_element(i) = free[1].local_element(i) = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double sum = product.local_element(i);
          if (!(sum > 0.))
            free[0].local_element(i) = free[1].local_element(i) = 0.;
          inverse_diagonal.local_element(i) = sum > 0. ? 1. / sum : 1.;
        }

      for (unsigned int d = 0; d < 2; ++d)
        {
          Vector &b = rhs[d];
          for (unsigned int i = 0; i < n_owned; ++i)
            b.local_element(i) *= free[d].local_element(i);
          Vector &x = increment[d];
          if (x.get_partitioner() != nodes.nodal_mass.get_partitioner())
            x.reinit(nodes.nodal_mass);
          x                 = 0.;
          const double norm = b.l2_norm();
          if (norm > 0.)
            {
              dealii::SolverControl    control(200, 1e-10 * norm);
              dealii::SolverCG<Vector> cg(control);
              try
                {
                  cg.solve(ComponentOperator{*this, d}, x, b, InverseDiagonal{inverse_diagonal});
                }
              catch (const dealii::SolverControl::NoConvergence &failure)
                {
                  throw RunFailure("the skeleton's drag increment (conjugate gradients) did "
                                   "not converge: residual "
                                   + to_string(failure.last_residual) + " after "
                                   + std::to_string(failure.last_step)
                                   + " iterations (reduce the time step)");
                }
            }
          x.update_ghost_values();
          nodes.interpolate_hanging_nodes(x);
        }
    }
  } // namespace granular
} // namespace slidewave
