#include <algorithm>
#include <cmath>
#include <slidewave/particles/point_count.h>

namespace slidewave
{
  namespace particles
  {
    double
    grid_cell_count(const dealii::Point<2> &lower_left,
                    const dealii::Point<2> &upper_right,
                    const double            cell_size)
    {
      if (!(cell_size > 0.))
        return 0.;
      return std::round((upper_right[0] - lower_left[0]) / cell_size)
             * std::round((upper_right[1] - lower_left[1]) / cell_size);
    }



    double
    point_count_bound(const std::vector<MaterialRegion> &regions,
                      const dealii::Point<2>            &lower_left,
                      const dealii::Point<2>            &upper_right,
                      const double                       cell_size,
                      const unsigned int                 per_direction)
    {
      const double per_cell = static_cast<double>(per_direction) * per_direction;
      const double all      = grid_cell_count(lower_left, upper_right, cell_size) * per_cell;
      double       count    = 0.;
      for (const auto &region : regions)
        {
          if (region.polygon.empty())
            return all;
          const auto [lower, upper] = region.bounding_box();
          double cells              = 1.;
          for (unsigned int d = 0; d < 2; ++d)
            {
              const double from = std::max(lower[d], lower_left[d]);
              const double to   = std::min(upper[d], upper_right[d]);
              cells *= std::max(0., std::ceil((to - from) / cell_size) + 1.);
            }
          count += cells * per_cell;
        }
      return std::min(count, all);
    }
  } // namespace particles
} // namespace slidewave
