#include <algorithm>
#include <slidewave/grid/cell_patches.h>

namespace slidewave
{
  namespace grid
  {
    CellPatches::CellPatches(const BackgroundGrid &grid, const NodalWorkspace &nodes)
      : grid(grid)
      , nodes(nodes)
    {
    }



    void
    CellPatches::reinit()
    {
      const auto &tria            = grid.triangulation();
      const auto &dofs            = grid.dof_handler();
      const auto &vertex_to_cells = grid.vertex_cells();
      patch_start.assign(tria.n_active_cells() + 1, 0);
      own_cell.assign(tria.n_active_cells(), grid::PatchCell{});
      patch_cells.clear();
      patch_cell_iterators.clear();
      // A cell and at most its 8 neighbours on a uniform grid (more next to finer cells):
      // reserved once, not regrown (regrowing copied the patches a few times over, a
      // quarter of the set-up of 10^6 cells).
      const std::size_t n_owned = tria.n_locally_owned_active_cells();
      patch_cells.reserve(9 * n_owned);
      patch_cell_iterators.reserve(9 * n_owned);
      std::vector<dealii::types::global_dof_index>    dof_indices(4);
      std::vector<BackgroundGrid::ActiveCellIterator> neighbours;
      const auto make_entry = [&](const dealii::DoFHandler<2>::active_cell_iterator &cell) {
        grid::PatchCell entry;
        entry.x0 = cell->vertex(0)[0];
        entry.y0 = cell->vertex(0)[1];
        entry.hx = cell->vertex(1)[0] - entry.x0;
        entry.hy = cell->vertex(2)[1] - entry.y0;
        cell->get_dof_indices(dof_indices);
        for (unsigned int a = 0; a < 4; ++a)
          entry.node[a] = nodes.local_index(dof_indices[a]);
        return entry;
      };
      for (const auto &cell : dofs.active_cell_iterators())
        {
          const unsigned int index = cell->active_cell_index();
          patch_start[index + 1]   = patch_start[index];
          if (!cell->is_locally_owned())
            continue;
          patch_cells.push_back(make_entry(cell));
          own_cell[index] = patch_cells.back();
          patch_cell_iterators.push_back(cell);
          neighbours.clear();
          for (const unsigned int v : cell->vertex_indices())
            for (const auto &other : vertex_to_cells[cell->vertex_index(v)])
              if (other != cell
                  && std::find(neighbours.begin(), neighbours.end(), other) == neighbours.end())
                neighbours.push_back(other);
          // In the order of their lower left corners (by rows, bottom up; no two active
          // cells share one), which depends on the grid only, not on the indices
          // refinement and coarsening happened to give the cells: a GIMP point's sums over
          // its patch then repeat in a run resumed from a checkpoint.
          std::sort(neighbours.begin(), neighbours.end(), [](const auto &a, const auto &b) {
            const dealii::Point<2> &pa = a->vertex(0), &pb = b->vertex(0);
            return pa[1] < pb[1] || (pa[1] == pb[1] && pa[0] < pb[0]);
          });
          for (const auto &other : neighbours)
            {
              patch_cells.push_back(make_entry(dealii::DoFHandler<2>::active_cell_iterator(
                &tria, other->level(), other->index(), &dofs)));
              patch_cell_iterators.push_back(other);
            }
          patch_start[index + 1] = patch_cells.size();
        }
    }
  } // namespace grid
} // namespace slidewave
