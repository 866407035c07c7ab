#ifndef slidewave_grid_grid_boundary_h
#define slidewave_grid_grid_boundary_h

namespace slidewave
{
  namespace grid
  {
    /** A velocity condition on a side of the background grid. */
    enum class GridBoundary
    {
      free,   ///< nothing imposed
      roller, ///< normal velocity zero (free slip)
      fixed   ///< both velocity components zero (no slip)
    };
  } // namespace grid
} // namespace slidewave

#endif
