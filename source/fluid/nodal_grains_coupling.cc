#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <slidewave/core/input_error.h>
#include <slidewave/fluid/nodal_grains_coupling.h>

namespace slidewave
{
  namespace fluid
  {
    namespace
    {
      /** One component's grains' operator, as the conjugate gradients call it. */
      template <class Coupling>
      struct ComponentOperator
      {
        const Coupling &coupling;
        unsigned int    d;
        void
        vmult(NodalGrainsCoupling::NodalVector &y, const NodalGrainsCoupling::NodalVector &x) const
        {
          coupling(d, y, x);
        }
      };

      /** Jacobi: the inverse row sums. */
      struct InverseDiagonal
      {
        const NodalGrainsCoupling::NodalVector &inverse;
        void
        vmult(NodalGrainsCoupling::NodalVector &y, const NodalGrainsCoupling::NodalVector &x) const
        {
          for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
            y.local_element(i) = inverse.local_element(i) * x.local_element(i);
        }
      };
    } // namespace



    NodalGrainsCoupling::NodalGrainsCoupling(const grid::BackgroundGrid &grid)
      : grid(grid)
    {
    }



    void
    NodalGrainsCoupling::begin(const NodalGrains &nodal_grains, const double step)
    {
      grains = nodal_grains;
      dt     = step;
      cells.clear();
      n_inner                 = 0;
      const NodalVector &mass = grains.nodes->nodal_mass;
      if (work.get_partitioner() != mass.get_partitioner())
        for (NodalVector *v :
             {&load[0], &load[1], &dv[0], &dv[1], &work, &product, &inverse_diagonal})
          v->reinit(mass);
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
      CellData data;
      data.cell_number = cell_number;
      std::vector<dealii::types::global_dof_index> grid_indices(4);
      grid_cell->get_dof_indices(grid_indices);
      for (unsigned int I = 0; I < 4; ++I)
        data.nodes[I] = grains.nodes->local_index(grid_indices[I]);
      data.drag.fill(0.);
      data.pressure.fill(0.);
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
                  data.drag[4 * I + J] += drag[q] * Ni * fv.shape_value(j, q) * JxW;
                  // (G p)_I = (1 - n_I) integral of N_I grad p, lumped on the node's grains;
                  // the continuity's div(N_J (1 - n_J) dv_J) tested by N_I
                  for (unsigned int d = 0; d < 2; ++d)
                    {
                      data.pressure[16 * d + 4 * I + J]
                        += (1. - fluid_fraction[I]) * Ni * Gj[d] * JxW;
                      data.flux[16 * d + 4 * I + J] += Ni * Gj[d] * (1. - fluid_fraction[J]) * JxW;
                    }
                }
            }
        }
      cells.push_back(data);
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
      product                           = 0.;
      for (const CellData &cell : cells)
        for (unsigned int I = 0; I < 4; ++I)
          for (unsigned int J = 0; J < 4; ++J)
            product.local_element(cell.nodes[I]) += cell.drag[4 * I + J];
      nodes.condense_hanging_nodes(product);
      product.compress(dealii::VectorOperation::add);
      for (unsigned int i = 0; i < product.locally_owned_size(); ++i)
        {
          const double sum = nodes.nodal_mass.local_element(i) / dt + product.local_element(i);
          inverse_diagonal.local_element(i) = sum > 0. ? 1. / sum : 1.;
        }
      // The known part: B dv(g) with the constraints' values g (and r_0).
      values = 0.;
      constraints.distribute(values);
      x_ghosted = values;
      grains_load(x_ghosted, true);
      solve_grains();
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
      solve_grains();
      water_load(out);
      y += out;
    }



    void
    NodalGrainsCoupling::compute_increment(const VectorType &solution)
    {
      x_ghosted = solution;
      grains_load(x_ghosted, true);
      solve_grains();
    }



    void
    NodalGrainsCoupling::grains_load(const VectorType &x, const bool with_known) const
    {
      const grid::NodalWorkspace &nodes = *grains.nodes;
      for (unsigned int d = 0; d < 2; ++d)
        load[d] = 0.;
      std::array<double, 12> dofs;
      for (unsigned int k = 0; k < cells.size(); ++k)
        {
          const CellData &cell = cells[k];
          gather->get(cell.cell_number, x, dofs.data());
          std::array<double, 4> p;
          for (unsigned int J = 0; J < 4; ++J)
            p[J] = dofs[position[3 * J + 2]] - (with_known ? old_pressure[4 * k + J] : 0.);
          for (unsigned int I = 0; I < 4; ++I)
            for (unsigned int d = 0; d < 2; ++d)
              {
                // D u - (1 - n_I) K (p - p^n) (- F v*_s)
                double r = with_known ? -cell.known[4 * d + I] : 0.;
                for (unsigned int J = 0; J < 4; ++J)
                  r += cell.drag[4 * I + J] * dofs[position[3 * J + d]]
                       - cell.pressure[16 * d + 4 * I + J] * p[J];
                load[d].local_element(cell.nodes[I]) += r;
              }
        }
      for (unsigned int d = 0; d < 2; ++d)
        {
          nodes.condense_hanging_nodes(load[d]);
          load[d].compress(dealii::VectorOperation::add);
          for (unsigned int i = 0; i < load[d].locally_owned_size(); ++i)
            load[d].local_element(i) *= grains.free[d]->local_element(i);
        }
    }



    void
    NodalGrainsCoupling::solve_grains() const
    {
      const grid::NodalWorkspace &nodes = *grains.nodes;
      for (unsigned int d = 0; d < 2; ++d)
        {
          NodalVector &x = dv[d];
          x.zero_out_ghost_values();
          x                 = 0.;
          const double norm = load[d].l2_norm();
          if (norm > 0.)
            {
              dealii::SolverControl         control(500, 1e-12 * norm);
              dealii::SolverCG<NodalVector> cg(control);
              const auto                    apply
                = [this](const unsigned int c, NodalVector &y, const NodalVector &v) {
                    grains_vmult(c, y, v);
                  };
              try
                {
                  cg.solve(ComponentOperator<decltype(apply)>{apply, d},
                           x,
                           load[d],
                           InverseDiagonal{inverse_diagonal});
                }
              catch (const dealii::SolverControl::NoConvergence &failure)
                {
                  throw RunFailure("the grains' nodal drag system (conjugate gradients) did "
                                   "not converge: residual "
                                   + to_string(failure.last_residual) + " after "
                                   + std::to_string(failure.last_step)
                                   + " iterations (reduce the time step)");
                }
              n_inner += control.last_step();
            }
          x.update_ghost_values();
          nodes.interpolate_hanging_nodes(x);
        }
    }



    void
    NodalGrainsCoupling::grains_vmult(const unsigned int d,
                                      NodalVector       &y,
                                      const NodalVector &x) const
    {
      const grid::NodalWorkspace &nodes   = *grains.nodes;
      const NodalVector          &free    = *grains.free[d];
      const unsigned int          n_owned = x.locally_owned_size();
      // x on the free nodes, the hanging ones from their parents.
      for (unsigned int i = 0; i < n_owned; ++i)
        work.local_element(i) = free.local_element(i) * x.local_element(i);
      work.update_ghost_values();
      nodes.interpolate_hanging_nodes(work);
      product = 0.;
      for (const CellData &cell : cells)
        for (unsigned int I = 0; I < 4; ++I)
          {
            double sum = 0.;
            for (unsigned int J = 0; J < 4; ++J)
              sum += cell.drag[4 * I + J] * work.local_element(cell.nodes[J]);
            product.local_element(cell.nodes[I]) += sum;
          }
      nodes.condense_hanging_nodes(product);
      product.compress(dealii::VectorOperation::add);
      work.zero_out_ghost_values();
      // M / dt + D on the free nodes, the identity elsewhere: symmetric, positive definite.
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          const double f     = free.local_element(i);
          y.local_element(i) = f
                                 * (nodes.nodal_mass.local_element(i) / dt * x.local_element(i)
                                    + product.local_element(i))
                               + (1. - f) * x.local_element(i);
        }
    }



    void
    NodalGrainsCoupling::water_load(VectorType &result) const
    {
      result = 0.;
      dealii::Vector<double>                       local(12);
      std::vector<dealii::types::global_dof_index> indices(12);
      for (const CellData &cell : cells)
        {
          local = 0.;
          for (unsigned int I = 0; I < 4; ++I)
            for (unsigned int J = 0; J < 4; ++J)
              {
                const unsigned int node = cell.nodes[J];
                // - D dv in the momentum; div(N_J (1 - n_J) dv_J) in the continuity
                for (unsigned int d = 0; d < 2; ++d)
                  {
                    const double v = dv[d].local_element(node);
                    local[position[3 * I + d]] -= cell.drag[4 * I + J] * v;
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
