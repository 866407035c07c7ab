#ifndef slidewave_grid_grid_follower_h
#define slidewave_grid_grid_follower_h

#include <deal.II/grid/tria.h>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * Anything that lives on the background grid and must follow the whole life of its
     * cells: the material points (they travel with their cells), the nodal workspace,
     * the velocity constraints and cell patches (rebuilt on the new cells), a
     * finite-element field (its vectors transferred, its own DoFHandler redistributed).
     *
     * The grid (BackgroundGrid) owns the cells; every physics on it attaches the objects
     * that hold its data as followers, and the grid calls each of them, in the order they
     * were attached, at every event of the cells' life:
     *
     * | event                                   | before                        | after |
     * |-----------------------------------------|-------------------------------|-----------------------|
     * | set-up (cells exist, grid dofs ready)   |                               | grid_ready() | |
     * refinement, coarsening, repartitioning  | prepare_for_grid_change()     | grid_changed() | |
     * checkpoint                              | prepare_for_checkpoint()      | | | resume (cells
     * read, grid dofs ready)    |                               | grid_ready(), then
     * checkpoint_loaded() |
     *
     * and asks each of them, when it decides how the cells change, for the cells it
     * needs fine (add_refinement_indicators()) and for its share of a cell's weight in the
     * partition (cell_weight()). Data a follower attaches to the cells for a change or a
     * checkpoint (deal.II's register_data_attach, used by ParticleHandler and
     * SolutionTransfer) is taken back in the same order as it was attached, so that a
     * resumed run on another number of ranks gets every follower's data back.
     *
     * Every duty has a default that does nothing: a follower implements what it holds.
     * Virtual calls once per event or once per cell of a partition, never per point.
     */
    class GridFollower
    {
    public:
      using CellIterator = dealii::Triangulation<2>::cell_iterator;
      using CellStatus   = dealii::Triangulation<2>::CellStatus;

      virtual ~GridFollower() = default;

      /** The cells exist and the grid's own degrees of freedom are distributed (set-up,
       *  and after a checkpoint was read): build what depends on the grid. */
      virtual void
      grid_ready()
      {
      }

      /** Before the cells change: attach what must travel with them. */
      virtual void
      prepare_for_grid_change()
      {
      }

      /** After the change (the grid's degrees of freedom already distributed on the new
       *  cells): take back what travelled and rebuild what depends on the grid. */
      virtual void
      grid_changed()
      {
      }

      /** Before the grid writes a checkpoint: attach this follower's data to the cells. */
      virtual void
      prepare_for_checkpoint()
      {
      }

      /** Before the grid reads a checkpoint, once its coarse cells exist: register what
       *  must receive data attached to the cells (a particle handler). */
      virtual void
      before_checkpoint_load()
      {
      }

      /** After the grid read a checkpoint and grid_ready() was called: take back the data
       *  prepare_for_checkpoint() attached (in the same order among the followers). */
      virtual void
      checkpoint_loaded()
      {
      }

      /**
       * Sets keep_fine[active cell index] = true for the locally owned cells this
       * follower needs at the finest level (material there, an interface, a steep
       * gradient); never clears a flag another follower set. The grid keeps those cells
       * (and a buffer around them) fine and coarsens the others.
       */
      virtual void
      add_refinement_indicators(std::vector<bool> & /*keep_fine*/) const
      {
      }

      /**
       * This follower's share of the partitioning weight of @p cell (the grid adds the
       * cell's own 1000 and the shares of all followers): its points, its degrees of
       * freedom, its work there. @p status as deal.II's 'weight' signal gives it.
       */
      virtual unsigned long long
      cell_weight(const CellIterator & /*cell*/, CellStatus /*status*/) const
      {
        return 0;
      }
    };
  } // namespace grid
} // namespace slidewave

#endif
