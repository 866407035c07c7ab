#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/nodal_cell_operator.h>

namespace slidewave
{
  namespace grid
  {
    namespace
    {
      /** One component's operator, as the conjugate gradients call it. */
      struct ComponentOperator
      {
        const NodalCellOperator &op;
        unsigned int             d;
        void
        vmult(NodalCellOperator::Vector &y, const NodalCellOperator::Vector &x) const
        {
          op.vmult(d, y, x);
        }
      };

      /** Both components' operator. */
      struct PairOperator
      {
        const NodalCellOperator &op;
        void
        vmult(NodalCellOperator::PairVector &y, const NodalCellOperator::PairVector &x) const
        {
          op.vmult(y, x);
        }
      };

      /** Jacobi: the inverse row sums, the same for both components. */
      struct InverseDiagonal
      {
        const NodalCellOperator::Vector &inverse;
        void
        vmult(NodalCellOperator::Vector &y, const NodalCellOperator::Vector &x) const
        {
          for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
            y.local_element(i) = inverse.local_element(i) * x.local_element(i);
        }
        void
        vmult(NodalCellOperator::PairVector &y, const NodalCellOperator::PairVector &x) const
        {
          for (unsigned int d = 0; d < 2; ++d)
            vmult(y.block(d), x.block(d));
        }
      };

      /** x = A^-1 b by preconditioned conjugate gradients to @p relative_tolerance of
       *  |b| (x zero where b is), its ghosts left to the caller; throws RunFailure naming
       *  @p what. Returns the iterations. */
      template <class VectorType, class OperatorType, class PreconditionerType>
      unsigned int
      conjugate_gradients(const OperatorType       &op,
                          VectorType               &x,
                          const VectorType         &b,
                          const PreconditionerType &preconditioner,
                          const double              relative_tolerance,
                          const unsigned int        max_iterations,
                          const std::string        &what)
      {
        x.zero_out_ghost_values();
        x                 = 0.;
        const double norm = b.l2_norm();
        if (norm == 0.)
          return 0;
        dealii::SolverControl        control(max_iterations, relative_tolerance * norm);
        dealii::SolverCG<VectorType> cg(control);
        try
          {
            cg.solve(op, x, b, preconditioner);
          }
        catch (const dealii::SolverControl::NoConvergence &failure)
          {
            throw RunFailure(what + " (conjugate gradients) did not converge: residual "
                             + to_string(failure.last_residual) + " after "
                             + std::to_string(failure.last_step)
                             + " iterations (reduce the time step)");
          }
        return control.last_step();
      }
    } // namespace



    void
    NodalCellOperator::reinit(const NodalWorkspace                &nodes,
                              const std::array<const Vector *, 2> &free_nodes)
    {
      workspace = &nodes;
      free      = free_nodes;
      if (work[0].get_partitioner() != nodes.nodal_mass.get_partitioner())
        {
          work[0].reinit(nodes.nodal_mass);
          product[0].reinit(nodes.nodal_mass);
        }
    }



    void
    NodalCellOperator::set_diagonal(const Vector *nodal_diagonal, const double scale)
    {
      diagonal       = nodal_diagonal;
      diagonal_scale = scale;
    }



    void
    NodalCellOperator::row_sums(Vector &sums, Vector &inverse_diagonal) const
    {
      sums = 0.;
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            sums.local_element(cell.nodes[i]) += cell.matrix[4 * i + j];
      workspace->condense_hanging_nodes(sums);
      sums.compress(dealii::VectorOperation::add);
      for (unsigned int i = 0; i < sums.locally_owned_size(); ++i)
        {
          double &sum = sums.local_element(i);
          if (diagonal != nullptr)
            sum += diagonal_scale * diagonal->local_element(i);
          inverse_diagonal.local_element(i) = sum > 0. ? 1. / sum : 1.;
        }
    }



    template <unsigned int n>
    void
    NodalCellOperator::apply(const std::array<unsigned int, n>   &component,
                             const std::array<Vector *, n>       &y,
                             const std::array<const Vector *, n> &x) const
    {
      const NodalWorkspace &nodes   = *workspace;
      const unsigned int    n_owned = x[0]->locally_owned_size();
      // x on the free nodes, the hanging ones from their parents.
      for (unsigned int c = 0; c < n; ++c)
        {
          const Vector &mask = *free[component[c]];
          for (unsigned int i = 0; i < n_owned; ++i)
            work[c].local_element(i) = mask.local_element(i) * x[c]->local_element(i);
          work[c].update_ghost_values_start(c);
        }
      for (unsigned int c = 0; c < n; ++c)
        {
          work[c].update_ghost_values_finish();
          nodes.interpolate_hanging_nodes(work[c]);
          product[c] = 0.;
        }
      // One pass over the cells' matrices for the n components.
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          {
            double sum[n] = {};
            for (unsigned int j = 0; j < 4; ++j)
              for (unsigned int c = 0; c < n; ++c)
                sum[c] += cell.matrix[4 * i + j] * work[c].local_element(cell.nodes[j]);
            for (unsigned int c = 0; c < n; ++c)
              product[c].local_element(cell.nodes[i]) += sum[c];
          }
      for (unsigned int c = 0; c < n; ++c)
        {
          nodes.condense_hanging_nodes(product[c]);
          product[c].compress_start(c, dealii::VectorOperation::add);
        }
      for (unsigned int c = 0; c < n; ++c)
        {
          product[c].compress_finish(dealii::VectorOperation::add);
          work[c].zero_out_ghost_values();
          // The identity on the other nodes: symmetric, positive definite.
          const Vector &mask = *free[component[c]];
          const Vector &xc = *x[c], &pc = product[c];
          Vector       &yc = *y[c];
          if (diagonal == nullptr)
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                const double f      = mask.local_element(i);
                yc.local_element(i) = f * pc.local_element(i) + (1. - f) * xc.local_element(i);
              }
          else
            for (unsigned int i = 0; i < n_owned; ++i)
              {
                const double f = mask.local_element(i);
                yc.local_element(i)
                  = f
                      * (diagonal_scale * diagonal->local_element(i) * xc.local_element(i)
                         + pc.local_element(i))
                    + (1. - f) * xc.local_element(i);
              }
        }
    }



    void
    NodalCellOperator::vmult(const unsigned int d, Vector &y, const Vector &x) const
    {
      apply<1>({{d}}, {{&y}}, {{&x}});
    }



    unsigned int
    NodalCellOperator::solve(const unsigned int d,
                             Vector            &x,
                             const Vector      &b,
                             const Vector      &inverse_diagonal,
                             const double       relative_tolerance,
                             const unsigned int max_iterations,
                             const std::string &what) const
    {
      const unsigned int iterations = conjugate_gradients(ComponentOperator{*this, d},
                                                          x,
                                                          b,
                                                          InverseDiagonal{inverse_diagonal},
                                                          relative_tolerance,
                                                          max_iterations,
                                                          what);
      x.update_ghost_values();
      workspace->interpolate_hanging_nodes(x);
      return iterations;
    }



    void
    NodalCellOperator::reinit_pair(PairVector &v, const Vector &layout)
    {
      if (v.n_blocks() == 2 && v.block(0).get_partitioner() == layout.get_partitioner())
        return;
      v.reinit(2);
      for (unsigned int d = 0; d < 2; ++d)
        v.block(d).reinit(layout);
      v.collect_sizes();
    }



    void
    NodalCellOperator::vmult(PairVector &y, const PairVector &x) const
    {
      if (work[1].get_partitioner() != work[0].get_partitioner())
        {
          work[1].reinit(work[0]);
          product[1].reinit(work[0]);
        }
      apply<2>({{0, 1}}, {{&y.block(0), &y.block(1)}}, {{&x.block(0), &x.block(1)}});
    }



    unsigned int
    NodalCellOperator::solve(PairVector        &x,
                             const PairVector  &b,
                             const Vector      &inverse_diagonal,
                             const double       relative_tolerance,
                             const unsigned int max_iterations,
                             const std::string &what) const
    {
      const unsigned int iterations = conjugate_gradients(PairOperator{*this},
                                                          x,
                                                          b,
                                                          InverseDiagonal{inverse_diagonal},
                                                          relative_tolerance,
                                                          max_iterations,
                                                          what);
      x.update_ghost_values();
      for (unsigned int d = 0; d < 2; ++d)
        workspace->interpolate_hanging_nodes(x.block(d));
      return iterations;
    }
  } // namespace grid
} // namespace slidewave
