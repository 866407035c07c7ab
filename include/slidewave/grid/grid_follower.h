#ifndef slidewave_grid_grid_follower_h
#define slidewave_grid_grid_follower_h

namespace slidewave
{
  namespace grid
  {
    /**
     * An object that lives on the background grid and must follow its changes: the
     * material points (they travel with their cells), the nodal workspace, the velocity
     * constraints and cell patches (rebuilt on the new cells), a finite-element fluid
     * later (its solution vectors transferred). BackgroundGrid calls every attached
     * follower, in the order they were attached, around each refinement, coarsening or
     * repartitioning: prepare_for_grid_change() before the cells change, grid_changed()
     * after, once the grid's own degrees of freedom are distributed on the new cells.
     * Virtual calls once per grid change, never per point.
     */
    class GridFollower
    {
    public:
      virtual ~GridFollower() = default;

      /** Before the cells change: attach what must travel with them. */
      virtual void
      prepare_for_grid_change()
        = 0;

      /** After the change: take back what travelled and rebuild what depends on the grid. */
      virtual void
      grid_changed()
        = 0;
    };
  } // namespace grid
} // namespace slidewave

#endif
