#ifndef slidewave_grid_tree_order_h
#define slidewave_grid_tree_order_h

#include <deal.II/dofs/dof_handler.h>

namespace slidewave
{
  namespace grid
  {
    /**
     * Calls @p visit(cell) for every locally owned active cell of @p dofs in the order of
     * the cells' tree: the coarse cells in turn, each refined cell's children in their
     * order. Unlike active_cell_iterators(), whose order follows the indices refinement
     * and coarsening happened to give the cells, this order depends only on the grid: a
     * sum over cells (an integral, an assembled matrix entry) comes out bit for bit the
     * same in a run resumed from a checkpoint as in the run that wrote it.
     */
    template <class Visitor>
    void
    for_each_owned_cell_in_tree_order(const dealii::DoFHandler<2> &dofs, const Visitor &visit)
    {
      using CellIterator = typename dealii::DoFHandler<2>::cell_iterator;
      const auto descend = [&](const CellIterator &cell, const auto &self) -> void {
        if (cell->has_children())
          {
            for (unsigned int c = 0; c < cell->n_children(); ++c)
              self(cell->child(c), self);
          }
        else if (cell->is_locally_owned())
          visit(typename dealii::DoFHandler<2>::active_cell_iterator(cell));
      };
      for (auto cell = dofs.begin(0); cell != dofs.end(0); ++cell)
        descend(cell, descend);
    }
  } // namespace grid
} // namespace slidewave

#endif
