#ifndef slidewave_linear_algebra_cell_gather_h
#define slidewave_linear_algebra_cell_gather_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <vector>

namespace slidewave
{
  namespace linear_algebra
  {
    /**
     * Where the degrees of freedom of each locally owned cell (numbered in tree order,
     * grid::for_each_owned_cell_in_tree_order) sit in the local array of a ghosted
     * Trilinos vector: reading a cell's values is then a plain array access instead of a
     * global-to-local lookup per degree of freedom (which a Trilinos vector does by
     * hashing). Built for one DoFHandler numbering and one ghosted layout; rebuild after
     * the degrees of freedom change.
     */
    class CellGather
    {
    public:
      using VectorType = dealii::TrilinosWrappers::MPI::Vector;

      /** The positions for @p dofs' owned cells in vectors laid out as @p ghosted. */
      void
      reinit(const dealii::DoFHandler<2> &dofs, const VectorType &ghosted);

      /** Forgets the positions (the degrees of freedom changed). */
      void
      clear()
      {
        positions.clear();
        layout.clear();
      }

      bool
      empty() const
      {
        return positions.empty();
      }

      /** The values of @p vector (laid out as the one given to reinit()) at the degrees
       *  of freedom of owned cell number @p cell, in the cell's local order. */
      void
      get(unsigned int cell, const VectorType &vector, double *values) const
      {
        AssertIndexRange(cell * n_dofs, positions.size());
        const double *local = vector.trilinos_vector()[0];
        const int    *p     = &positions[cell * n_dofs];
        for (unsigned int i = 0; i < n_dofs; ++i)
          values[i] = local[p[i]];
      }

      /** Whether @p vector has the layout the positions were made for. */
      bool
      matches(const VectorType &vector) const;

    private:
      unsigned int     n_dofs = 0;
      std::vector<int> positions;
      std::vector<int> layout; // the ghosted vector's global indices, in its local order
    };
  } // namespace linear_algebra
} // namespace slidewave

#endif
