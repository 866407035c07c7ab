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

      /** Jacobi: the inverse row sums. */
      struct InverseDiagonal
      {
        const NodalCellOperator::Vector &inverse;
        void
        vmult(NodalCellOperator::Vector &y, const NodalCellOperator::Vector &x) const
        {
          for (unsigned int i = 0; i < y.locally_owned_size(); ++i)
            y.local_element(i) = inverse.local_element(i) * x.local_element(i);
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

      /** Jacobi on both components: the same inverse row sums. */
      struct PairInverseDiagonal
      {
        const NodalCellOperator::Vector &inverse;
        void
        vmult(NodalCellOperator::PairVector &y, const NodalCellOperator::PairVector &x) const
        {
          for (unsigned int d = 0; d < 2; ++d)
            for (unsigned int i = 0; i < y.block(d).locally_owned_size(); ++i)
              y.block(d).local_element(i) = inverse.local_element(i) * x.block(d).local_element(i);
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
      if (work.get_partitioner() != nodes.nodal_mass.get_partitioner())
        {
          work.reinit(nodes.nodal_mass);
          product.reinit(nodes.nodal_mass);
        }
    }



    void
    NodalCellOperator::set_diagonal(const Vector *nodal_diagonal, const double scale)
    {
      diagonal       = nodal_diagonal;
      diagonal_scale = scale;
    }



    void
    NodalCellOperator::row_sums(Vector &sums) const
    {
      sums = 0.;
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          for (unsigned int j = 0; j < 4; ++j)
            sums.local_element(cell.nodes[i]) += cell.matrix[4 * i + j];
      workspace->condense_hanging_nodes(sums);
      sums.compress(dealii::VectorOperation::add);
    }



    void
    NodalCellOperator::vmult(const unsigned int d, Vector &y, const Vector &x) const
    {
      const NodalWorkspace &nodes   = *workspace;
      const Vector         &mask    = *free[d];
      const unsigned int    n_owned = x.locally_owned_size();
      // x on the free nodes, the hanging ones from their parents.
      for (unsigned int i = 0; i < n_owned; ++i)
        work.local_element(i) = mask.local_element(i) * x.local_element(i);
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
      // The identity on the other nodes: symmetric, positive definite.
      if (diagonal == nullptr)
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double f     = mask.local_element(i);
            y.local_element(i) = f * product.local_element(i) + (1. - f) * x.local_element(i);
          }
      else
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double f = mask.local_element(i);
            y.local_element(i)
              = f
                  * (diagonal_scale * diagonal->local_element(i) * x.local_element(i)
                     + product.local_element(i))
                + (1. - f) * x.local_element(i);
          }
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
      const NodalWorkspace &nodes = *workspace;
      reinit_pair(pair_work, work);
      reinit_pair(pair_product, work);
      const unsigned int n_owned = work.locally_owned_size();
      // As vmult(d, ...), the two components' exchanges overlapped and one pass over the
      // cells' matrices for both.
      for (unsigned int d = 0; d < 2; ++d)
        for (unsigned int i = 0; i < n_owned; ++i)
          pair_work.block(d).local_element(i)
            = free[d]->local_element(i) * x.block(d).local_element(i);
      pair_work.update_ghost_values();
      for (unsigned int d = 0; d < 2; ++d)
        nodes.interpolate_hanging_nodes(pair_work.block(d));
      pair_product        = 0.;
      const Vector &work0 = pair_work.block(0), &work1 = pair_work.block(1);
      Vector       &product0 = pair_product.block(0), &product1 = pair_product.block(1);
      for (const CellMatrix &cell : cells)
        for (unsigned int i = 0; i < 4; ++i)
          {
            double sum0 = 0., sum1 = 0.;
            for (unsigned int j = 0; j < 4; ++j)
              {
                sum0 += cell.matrix[4 * i + j] * work0.local_element(cell.nodes[j]);
                sum1 += cell.matrix[4 * i + j] * work1.local_element(cell.nodes[j]);
              }
            product0.local_element(cell.nodes[i]) += sum0;
            product1.local_element(cell.nodes[i]) += sum1;
          }
      for (unsigned int d = 0; d < 2; ++d)
        nodes.condense_hanging_nodes(pair_product.block(d));
      pair_product.compress(dealii::VectorOperation::add);
      pair_work.zero_out_ghost_values();
      for (unsigned int d = 0; d < 2; ++d)
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            const double f = free[d]->local_element(i);
            const double diagonal
              = this->diagonal == nullptr ? 0. : diagonal_scale * this->diagonal->local_element(i);
            y.block(d).local_element(i) = f
                                            * (diagonal * x.block(d).local_element(i)
                                               + pair_product.block(d).local_element(i))
                                          + (1. - f) * x.block(d).local_element(i);
          }
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
                                                          PairInverseDiagonal{inverse_diagonal},
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
