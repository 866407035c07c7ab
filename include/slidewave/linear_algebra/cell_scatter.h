#ifndef slidewave_linear_algebra_cell_scatter_h
#define slidewave_linear_algebra_cell_scatter_h

#include <cstdint>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>
#include <vector>

namespace slidewave
{
  namespace linear_algebra
  {
    /**
     * Adds the local matrices and right-hand sides of the locally owned cells (numbered in
     * tree order, grid::for_each_owned_cell_in_tree_order) into a Trilinos matrix and
     * vector. A cell none of whose degrees of freedom is constrained and all of whose rows
     * this rank owns (most cells) adds its entries directly where they sit in the
     * matrix's rows, found once when the sparsity is set up: no global-to-local lookup
     * and no search in the row per entry, which dominate a Trilinos assembly. Every other
     * cell goes through AffineConstraints::distribute_local_to_global(). Both add the
     * same numbers in the same order: the matrix is the same bit for bit.
     *
     * Bound to one matrix (its sparsity) and one numbering of the degrees of freedom;
     * rebuild after either changes.
     */
    class CellScatter
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /** The positions of @p dofs' owned cells' entries in @p matrix and @p rhs. */
      void
      reinit(const dealii::DoFHandler<2>                  &dofs,
             const dealii::AffineConstraints<double>      &constraints,
             const dealii::TrilinosWrappers::SparseMatrix &matrix,
             const VectorType                             &rhs);

      /** Forgets the positions (the sparsity or the numbering changed). */
      void
      clear()
      {
        first_row.clear();
        rows.clear();
        columns.clear();
        rhs_rows.clear();
      }

      bool
      empty() const
      {
        return first_row.empty();
      }

      /** Adds owned cell number @p cell's @p local_matrix and @p local_rhs (@p indices:
       *  its degrees of freedom, for the cells that need the constraints). */
      void
      add(unsigned int                                        cell,
          const dealii::FullMatrix<double>                   &local_matrix,
          const dealii::Vector<double>                       &local_rhs,
          const std::vector<dealii::types::global_dof_index> &indices,
          const dealii::AffineConstraints<double>            &constraints,
          dealii::TrilinosWrappers::SparseMatrix             &matrix,
          VectorType                                         &rhs) const;

      /** Adds owned cell number @p cell's @p local_matrix alone (as add() does; the
       *  constrained cells through the constraints' matrix-only distribution, whose
       *  entries are add()'s). */
      void
      add_matrix(unsigned int                                        cell,
                 const dealii::FullMatrix<double>                   &local_matrix,
                 const std::vector<dealii::types::global_dof_index> &indices,
                 const dealii::AffineConstraints<double>            &constraints,
                 dealii::TrilinosWrappers::SparseMatrix             &matrix) const;

      /** The share of the owned cells that add directly. */
      double
      direct_fraction() const;

    private:
      /** Adds @p local_matrix to the rows of the direct cell whose first entry is
       *  @p first. */
      void
      add_rows(int                                     first,
               const dealii::FullMatrix<double>       &local_matrix,
               dealii::TrilinosWrappers::SparseMatrix &matrix) const;

      unsigned int n_dofs = 0;
      /** Per cell: its first entry in rows and rhs_rows, or -1 (through the constraints). */
      std::vector<int> first_row;
      /** Per direct cell and local row: the matrix's local row. */
      std::vector<int> rows;
      /** Per direct cell, local row and local column: the entry's position in the row. */
      std::vector<std::uint16_t> columns;
      /** Per direct cell and local row: the right-hand side's local index. */
      std::vector<int> rhs_rows;
    };
  } // namespace linear_algebra
} // namespace slidewave

#endif
