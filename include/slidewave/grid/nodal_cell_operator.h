#ifndef slidewave_grid_nodal_cell_operator_h
#define slidewave_grid_nodal_cell_operator_h

#include <array>
#include <deal.II/lac/la_parallel_block_vector.h>
#include <slidewave/grid/nodal_workspace.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * A symmetric operator on the nodes of the nodal workspace, assembled from 4 x 4 cell
     * matrices (the same for each component), plus optionally a nodal diagonal, with per
     * component the nodes it solves for (free = 1) and the identity on the others (the
     * held components, the hanging nodes, which take their parents' values, and the empty
     * nodes): the weighted mass matrices of the granular couplings
     * (granular::DragProjection, fluid::NodalGrainsCoupling), applied without a global
     * matrix and solved by conjugate gradients with the inverse row sums, per component
     * (solve(d, ...): DragProjection) or both components in one run (solve() of a pair:
     * NodalGrainsCoupling).
     */
    class NodalCellOperator
    {
    public:
      using Vector = NodalWorkspace::Vector;
      /** The two components as blocks 0 and 1 of one vector (each of the layout). */
      using PairVector = dealii::LinearAlgebra::distributed::BlockVector<double>;

      /** A cell: its nodes' local indices and its matrix (row-major). */
      struct CellMatrix
      {
        std::array<unsigned int, 4> nodes;
        std::array<double, 16>      matrix;
      };

      /** Binds the operator to @p nodes (its work vectors to their layout) and to the
       *  masks @p free of the two components (that layout; kept by the caller). */
      void
      reinit(const NodalWorkspace &nodes, const std::array<const Vector *, 2> &free);

      /** The cells' matrices (filled by the owner after reinit()). */
      std::vector<CellMatrix> cells;

      /** With @p diagonal (the layout's owned values, kept by the caller) times
       *  @p scale added on the free nodes; null: none. */
      void
      set_diagonal(const Vector *diagonal, double scale);

      /** The operator's row sums at the owned nodes into @p sums: the cells' matrices'
       *  (hanging nodes' to their parents) plus the diagonal (on every owned node); and
       *  the conjugate gradients' preconditioner from them into @p inverse_diagonal:
       *  1 / sum where the sum is positive, 1 elsewhere (the layout; collective). */
      void
      row_sums(Vector &sums, Vector &inverse_diagonal) const;

      /** y = A x for component @p d (collective). */
      void
      vmult(unsigned int d, Vector &y, const Vector &x) const;

      /** x = A^-1 b for component @p d (b zero on the non-free nodes) by conjugate
       *  gradients to @p relative_tolerance of |b| within @p max_iterations, preconditioned
       *  by @p inverse_diagonal; x's ghosts and hanging nodes then set. Throws RunFailure
       *  naming @p what when they do not converge. Returns the iterations (collective). */
      unsigned int
      solve(unsigned int       d,
            Vector            &x,
            const Vector      &b,
            const Vector      &inverse_diagonal,
            double             relative_tolerance,
            unsigned int       max_iterations,
            const std::string &what) const;

      /** @p v a pair of vectors of @p layout's layout, unless it is one already. */
      static void
      reinit_pair(PairVector &v, const Vector &layout);

      /** y = A x for both components (blocks 0 and 1), their ghost exchanges overlapped
       *  (collective). */
      void
      vmult(PairVector &y, const PairVector &x) const;

      /** x = A^-1 b for both components at once: one conjugate-gradient run on the pair,
       *  whose global sums serve the two components and whose ghost exchanges overlap
       *  (two solve() runs would make a set each), to
       *  @p relative_tolerance of the pair's norm |b|, each component preconditioned by
       *  @p inverse_diagonal; x's ghosts and hanging nodes then set. Throws RunFailure
       *  naming @p what when it does not converge. Returns the iterations (collective). */
      unsigned int
      solve(PairVector        &x,
            const PairVector  &b,
            const Vector      &inverse_diagonal,
            double             relative_tolerance,
            unsigned int       max_iterations,
            const std::string &what) const;

    private:
      const NodalWorkspace         *workspace = nullptr;
      std::array<const Vector *, 2> free{};
      const Vector                 *diagonal       = nullptr;
      double                        diagonal_scale = 0.;
      /** Work vectors per component of a product (the second made by the first paired
       *  product of a layout). */
      mutable std::array<Vector, 2> work, product;

      /** y[c] = A x[c] for the @p n components @p component[c]: their ghost exchanges
       *  overlapped and one pass over the cells (collective). */
      template <unsigned int n>
      void
      apply(const std::array<unsigned int, n>   &component,
            const std::array<Vector *, n>       &y,
            const std::array<const Vector *, n> &x) const;
    };
  } // namespace grid
} // namespace slidewave

#endif
