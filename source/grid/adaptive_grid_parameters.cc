#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/adaptive_grid_parameters.h>

namespace slidewave
{
  namespace grid
  {
    void
    AdaptiveGridParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Enable",
                        "false",
                        Bool(),
                        "Refine the grid to 'Cell size' where the material is and 'Buffer "
                        "cells' layers around it (ahead of the flow), keep it 2^Levels times "
                        "coarser elsewhere and coarsen it behind the flow, every 'Interval' "
                        "steps: memory and set-up then scale with the area the flow covers, "
                        "not with the domain (doc/terrain.md, 'A grid that follows the "
                        "flow'). The hazard maps stay on the pixels of 'Cell size'.");
      prm.declare_entry("Levels",
                        "3",
                        Integer(1, 8),
                        "Refinement levels: the coarsest cells are 2^Levels times 'Cell "
                        "size', which must divide the domain (with 'Extent = terrain "
                        "raster' the domain is fitted to them).");
      prm.declare_entry("Buffer cells",
                        "8",
                        Integer(0, 100),
                        "Layers of cells of 'Cell size' kept around the material. The "
                        "columns travel at most 'Courant number' cells per step, so the "
                        "buffer must exceed 'Courant number' x 'Interval' plus the "
                        "columns' reach of one cell (refused otherwise).");
      prm.declare_entry("Interval",
                        "10",
                        Integer(1),
                        "Steps between adaptations (each rebuilds the grid's dofs, patches "
                        "and the particle handler's caches: a few steps' cost).");
    }



    void
    AdaptiveGridParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &)
    {
      enabled      = prm.get_bool("Enable");
      levels       = prm.get_integer("Levels");
      buffer_cells = prm.get_integer("Buffer cells");
      interval     = prm.get_integer("Interval");
    }



    void
    AdaptiveGridParameters::check_divides(const dealii::Point<2> &lower_left,
                                          const dealii::Point<2> &upper_right,
                                          const double            cell_size,
                                          const std::string      &path) const
    {
      if (!enabled)
        return;
      const double base = cell_size * (1u << levels);
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double n = (upper_right[d] - lower_left[d]) / base;
          if (std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
            throw InputError(path + "/Levels",
                             std::to_string(levels),
                             "a number of levels such that the coarsest cells (Cell size x "
                             "2^Levels = "
                               + to_string(base) + " m) divide the domain sides ("
                               + to_string(upper_right[0] - lower_left[0]) + " x "
                               + to_string(upper_right[1] - lower_left[1]) + " m)");
        }
    }
  } // namespace grid
} // namespace slidewave
