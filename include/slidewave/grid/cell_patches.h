#ifndef slidewave_grid_cell_patches_h
#define slidewave_grid_cell_patches_h

#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/grid_follower.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/shape_functions.h>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * For each locally owned cell, its patch: the cell itself and the active cells sharing
     * a vertex with it, as densely stored boxes with the local indices of their Q1 nodes
     * (grid::PatchCell). It is the reach of a GIMP point (paper 000, Eq. 11: the point's
     * domain stays within the patch of its cell) and where a point that moved less than
     * a cell is looked for (PointCloud::relocate_within_patches). Each owned cell's own
     * entry is also kept by active cell index (what Q1 reads for every point). A
     * GridFollower: rebuilt on every change of the grid.
     */
    class CellPatches : public GridFollower
    {
    public:
      CellPatches(const BackgroundGrid &grid, const NodalWorkspace &nodes);

      /** The patches of the current grid. */
      void
      reinit();

      void
      grid_ready() override
      {
        reinit();
      }

      void
      grid_changed() override
      {
        reinit();
      }

      /** The owned cell of active index @p cell_index itself. */
      const grid::PatchCell &
      own(const unsigned int cell_index) const
      {
        return own_cell[cell_index];
      }

      /** Entries of the patch of @p cell_index: [start(c), start(c + 1)), the cell first. */
      unsigned int
      start(const unsigned int cell_index) const
      {
        return patch_start[cell_index];
      }

      const grid::PatchCell &
      entry(const unsigned int e) const
      {
        return patch_cells[e];
      }

      const grid::PatchCell *
      begin(const unsigned int cell_index) const
      {
        return patch_cells.data() + patch_start[cell_index];
      }

      const grid::PatchCell *
      end(const unsigned int cell_index) const
      {
        return patch_cells.data() + patch_start[cell_index + 1];
      }

      /** The cell of entry @p e. */
      const BackgroundGrid::ActiveCellIterator &
      cell(const unsigned int e) const
      {
        return patch_cell_iterators[e];
      }

    private:
      const BackgroundGrid &grid;
      const NodalWorkspace &nodes;

      /** Each owned cell's own entry, by active cell index (a copy of the first of its
       * patch): what Q1 and the relocation read for every point, densely stored. */
      std::vector<grid::PatchCell> own_cell;
      /** Cells of each owned cell's patch: patch_cells[patch_start[c] .. patch_start[c+1]),
       * the cell itself first. */
      std::vector<unsigned int>    patch_start;
      std::vector<grid::PatchCell> patch_cells;
      /** The cell of each entry of patch_cells. */
      std::vector<BackgroundGrid::ActiveCellIterator> patch_cell_iterators;
    };
  } // namespace grid
} // namespace slidewave

#endif
