#include <algorithm>
#include <deal.II/base/mpi.h>
#include <slidewave/fluid/nodal_grains_coupling.h>

namespace slidewave
{
  namespace fluid
  {
    NodalGrainsCoupling::NodalGrainsCoupling(const grid::BackgroundGrid &grid)
      : grid(grid)
      , grid_indices(4)
    {
    }



    void
    NodalGrainsCoupling::begin(const NodalGrains &nodal_grains, const double step)
    {
      grains = nodal_grains;
      dt     = step;
      cells.clear();
      grains_operator.cells.clear();
      const NodalVector &mass = grains.nodes->nodal_mass;
      if (sums.get_partitioner() != mass.get_partitioner())
        for (NodalVector *v : {&sums, &inverse_diagonal})
          v->reinit(mass);
      grid::NodalCellOperator::reinit_pair(load, mass);
      grid::NodalCellOperator::reinit_pair(dv, mass);
    }



    void
    NodalGrainsCoupling::add_cell(const unsigned int                                 cell_number,
                                  const dealii::DoFHandler<2>::active_cell_iterator &grid_cell,
                                  const dealii::FEValues<2>                         &fv,
                                  const std::vector<unsigned int>                   &component,
                                  const std::vector<unsigned int>                   &vertex,
                                  const std::vector<double>                         &drag,
                                  const std::vector<dealii::Tensor<1, 2>>           &v_s,
                                  const std::vector<double>                         &fluid_fraction,
                                  const std::vector<dealii::types::global_dof_index> &indices)
    {
      AssertDimension(indices.size(), 12);
      CellData                            data;
      grid::NodalCellOperator::CellMatrix block;
      data.cell_number = cell_number;
      grid_cell->get_dof_indices(grid_indices);
      for (unsigned int I = 0; I < 4; ++I)
        block.nodes[I] = grains.nodes->local_index(grid_indices[I]);
      block.matrix.fill(0.);
      data.flux.fill(0.);
      data.known.fill(0.);
      for (unsigned int i = 0; i < 12; ++i)
        {
          data.indices[i]                        = indices[i];
          position[3 * vertex[i] + component[i]] = i;
        }
      // The vertices' scalar shape functions: those of the pressure's component.
      for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
        {
          const double JxW = fv.JxW(q);
          for (unsigned int I = 0; I < 4; ++I)
            {
              const double Ni = fv.shape_value(position[3 * I + 2], q);
              for (unsigned int d = 0; d < 2; ++d)
                data.known[4 * d + I] += Ni * drag[q] * v_s[q][d] * JxW;
              for (unsigned int J = 0; J < 4; ++J)
                {
                  const unsigned int         j  = position[3 * J + 2];
                  const dealii::Tensor<1, 2> Gj = fv.shape_grad(j, q);
                  block.matrix[4 * I + J] += drag[q] * Ni * fv.shape_value(j, q) * JxW;
                  // the continuity's div(N_J (1 - n_J) dv_J) tested by N_I (its transpose
                  // is the pressure's force on the grains: grains_load())
                  for (unsigned int d = 0; d < 2; ++d)
                    data.flux[16 * d + 4 * I + J] += Ni * Gj[d] * (1. - fluid_fraction[J]) * JxW;
                }
            }
        }
      cells.push_back(data);
      grains_operator.cells.push_back(block);
    }



    void
    NodalGrainsCoupling::finish(const dealii::AffineConstraints<double> &constraints,
                                const linear_algebra::CellGather        &flow_gather,
                                const VectorType                        &flow_old,
                                VectorType                              &rhs)
    {
      gather           = &flow_gather;
      flow_constraints = &constraints;
      // (collective: every rank makes its vectors anew when any rank's layout changed)
      const bool changed = x_owned.size() != rhs.size()
                           || x_owned.locally_owned_elements() != rhs.locally_owned_elements()
                           || !gather->matches(x_ghosted);
      if (dealii::Utilities::MPI::max(changed ? 1 : 0, grid.communicator()) > 0)
        {
          x_owned.reinit(rhs);
          out.reinit(rhs);
          values.reinit(rhs);
          x_ghosted.reinit(flow_old);
        }
      // The old pressure at the cells' vertices.
      std::array<double, 12> dofs;
      old_pressure.resize(4 * cells.size());
      for (unsigned int k = 0; k < cells.size(); ++k)
        {
          gather->get(cells[k].cell_number, flow_old, dofs.data());
          for (unsigned int J = 0; J < 4; ++J)
            old_pressure[4 * k + J] = dofs[position[3 * J + 2]];
        }
      // The grains' row sums: the conjugate gradients' preconditioner.
      const grid::NodalWorkspace &nodes = *grains.nodes;
      grains_operator.reinit(nodes, grains.free);
      grains_operator.set_diagonal(&nodes.nodal_mass, 1. / dt);
      grains_operator.row_sums(sums, inverse_diagonal);
      // The known part: B dv(g) with the constraints' values g (and r_0).
      values = 0.;
      constraints.distribute(values);
      x_ghosted = values;
      grains_load(x_ghosted, true);
      solve_grains(strict_tolerance);
      water_load(out);
      rhs -= out;
    }



    void
    NodalGrainsCoupling::vmult_add(VectorType &y, const VectorType &x) const
    {
      // The constraints without their values: distribute() is affine, its values g.
      x_owned = x;
      flow_constraints->distribute(x_owned);
      x_owned -= values;
      x_ghosted = x_owned;
      grains_load(x_ghosted, false);
      inner_iterations += solve_grains(product_tolerance);
      ++products;
      water_load(out);
      y += out;
    }



    void
    NodalGrainsCoupling::start_solve()
    {
      product_tolerance = strict_tolerance;
      products          = 0;
      inner_iterations  = 0;
    }



    void
    NodalGrainsCoupling::relax_products(const double outer_tolerance,
                                        const double residual_ratio,
                                        const bool   strict)
    {
      product_tolerance
        = strict || !(residual_ratio > 0.) ?
            strict_tolerance :
            std::clamp(0.1 * outer_tolerance / residual_ratio, strict_tolerance, 1e-3);
    }



    void
    NodalGrainsCoupling::compute_increment(const VectorType &solution)
    {
      x_ghosted = solution;
      grains_load(x_ghosted, true);
      solve_grains(strict_tolerance);
    }



    void
    NodalGrainsCoupling::grains_load(const VectorType &x, const bool with_known) const
    {
      const grid::NodalWorkspace &nodes = *grains.nodes;
      for (unsigned int d = 0; d < 2; ++d)
        load.block(d) = 0.;
      std::array<double, 12> dofs;
      for (unsigned int k = 0; k < cells.size(); ++k)
        {
          const CellData                            &cell  = cells[k];
          const grid::NodalCellOperator::CellMatrix &block = grains_operator.cells[k];
          gather->get(cell.cell_number, x, dofs.data());
          std::array<double, 4> p;
          for (unsigned int J = 0; J < 4; ++J)
            p[J] = dofs[position[3 * J + 2]] - (with_known ? old_pressure[4 * k + J] : 0.);
          for (unsigned int I = 0; I < 4; ++I)
            for (unsigned int d = 0; d < 2; ++d)
              {
                // D u - G (p - p^n) (- F v*_s), G = -(the continuity's flux)^T
                double r = with_known ? -cell.known[4 * d + I] : 0.;
                for (unsigned int J = 0; J < 4; ++J)
                  r += block.matrix[4 * I + J] * dofs[position[3 * J + d]]
                       + cell.flux[16 * d + 4 * J + I] * p[J];
                load.block(d).local_element(block.nodes[I]) += r;
              }
        }
      for (unsigned int d = 0; d < 2; ++d)
        nodes.condense_hanging_nodes(load.block(d));
      load.compress(dealii::VectorOperation::add);
      for (unsigned int d = 0; d < 2; ++d)
        for (unsigned int i = 0; i < load.block(d).locally_owned_size(); ++i)
          load.block(d).local_element(i) *= grains.free[d]->local_element(i);
    }



    double
    NodalGrainsCoupling::iterations_per_product() const
    {
      return products > 0 ? static_cast<double>(inner_iterations) / products : 0.;
    }



    unsigned int
    NodalGrainsCoupling::solve_grains(const double tolerance) const
    {
      return grains_operator.solve(
        dv, load, inverse_diagonal, tolerance, 500, "the grains' nodal drag system");
    }



    void
    NodalGrainsCoupling::water_load(VectorType &result) const
    {
      result = 0.;
      dealii::Vector<double>                       local(12);
      std::vector<dealii::types::global_dof_index> indices(12);
      for (unsigned int k = 0; k < cells.size(); ++k)
        {
          const CellData                            &cell  = cells[k];
          const grid::NodalCellOperator::CellMatrix &block = grains_operator.cells[k];
          local                                            = 0.;
          for (unsigned int I = 0; I < 4; ++I)
            for (unsigned int J = 0; J < 4; ++J)
              {
                const unsigned int node = block.nodes[J];
                // - D dv in the momentum; div(N_J (1 - n_J) dv_J) in the continuity
                for (unsigned int d = 0; d < 2; ++d)
                  {
                    const double v = dv.block(d).local_element(node);
                    local[position[3 * I + d]] -= block.matrix[4 * I + J] * v;
                    local[position[3 * I + 2]] += cell.flux[16 * d + 4 * I + J] * v;
                  }
              }
          std::copy(cell.indices.begin(), cell.indices.end(), indices.begin());
          // (a vector alone: the constraints' values play no part)
          flow_constraints->distribute_local_to_global(local, indices, result);
        }
      result.compress(dealii::VectorOperation::add);
    }
  } // namespace fluid
} // namespace slidewave
