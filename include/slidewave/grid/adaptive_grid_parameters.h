#ifndef slidewave_grid_adaptive_grid_parameters_h
#define slidewave_grid_adaptive_grid_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <string>

namespace slidewave
{
  namespace grid
  {
    /**
     * An "Adaptive grid" subsection of a flow over a terrain (the depth-averaged flow,
     * issue 28): a base grid 2^Levels times coarser than 'Cell size', refined to 'Cell
     * size' where the material is and 'Buffer cells' layers around it, coarsened behind,
     * every 'Interval' steps (BackgroundGrid, GridChanges).
     */
    struct AdaptiveGridParameters
    {
      /** Declares the entries (the handler inside the "Adaptive grid" subsection). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads the entries; @p path names the subsection in errors. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** Refuses (InputError naming 'Levels') a base cell, @p cell_size x 2^Levels, that
       *  does not divide the sides of [@p lower_left, @p upper_right]; @p path names the
       *  subsection. Nothing when disabled. */
      void
      check_divides(const dealii::Point<2> &lower_left,
                    const dealii::Point<2> &upper_right,
                    double                  cell_size,
                    const std::string      &path) const;

      /** Refinement levels above the base grid the grid uses (0 when disabled). */
      unsigned int
      used_levels() const
      {
        return enabled ? levels : 0;
      }

      bool         enabled      = false;
      unsigned int levels       = 3;
      unsigned int buffer_cells = 8;
      unsigned int interval     = 10;
    };
  } // namespace grid
} // namespace slidewave

#endif
