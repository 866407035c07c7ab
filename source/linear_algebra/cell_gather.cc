#include <algorithm>
#include <slidewave/grid/tree_order.h>
#include <slidewave/linear_algebra/cell_gather.h>
#include <stdexcept>

namespace slidewave
{
  namespace linear_algebra
  {
    void
    CellGather::reinit(const dealii::DoFHandler<2> &dofs, const VectorType &ghosted)
    {
      const Epetra_BlockMap &map = ghosted.trilinos_vector().Map();
      n_dofs                     = dofs.get_fe().n_dofs_per_cell();
      positions.clear();
      std::vector<dealii::types::global_dof_index> indices(n_dofs);
      grid::for_each_owned_cell_in_tree_order(dofs, [&](const auto &cell) {
        cell->get_dof_indices(indices);
        for (const auto index : indices)
          {
            const int position
              = map.LID(static_cast<dealii::TrilinosWrappers::types::int_type>(index));
            if (position < 0)
              throw std::logic_error("CellGather: a degree of freedom of an owned cell is not "
                                     "in the ghosted vector");
            positions.push_back(position);
          }
      });
      layout.assign(map.MyGlobalElements(), map.MyGlobalElements() + map.NumMyElements());
    }



    bool
    CellGather::matches(const VectorType &vector) const
    {
      // Local and cheap (no communication): the same global indices in the same order.
      const Epetra_BlockMap &map = vector.trilinos_vector().Map();
      return static_cast<std::size_t>(map.NumMyElements()) == layout.size()
             && std::equal(layout.begin(), layout.end(), map.MyGlobalElements());
    }
  } // namespace linear_algebra
} // namespace slidewave
