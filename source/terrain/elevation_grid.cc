#include <cmath>
#include <deal.II/base/exceptions.h>
#include <slidewave/terrain/elevation_grid.h>
#include <string>

namespace slidewave
{
  namespace terrain
  {
    ElevationGrid::ElevationGrid(const dealii::Point<2> &origin,
                                 const double            dx,
                                 const double            dy,
                                 const unsigned int      nx,
                                 const unsigned int      ny,
                                 std::vector<double>     values,
                                 const bool              with_gaps)
      : origin(origin)
      , dx(dx)
      , dy(dy)
      , nx(nx)
      , ny(ny)
      , z(std::move(values))
    {
      AssertThrow(nx >= 2 && ny >= 2 && dx > 0. && dy > 0.,
                  dealii::ExcMessage("An elevation grid needs at least 2 x 2 nodes and "
                                     "positive spacings."));
      AssertThrow(z.size() == static_cast<std::size_t>(nx) * ny,
                  dealii::ExcMessage("An elevation grid of " + std::to_string(nx) + " x "
                                     + std::to_string(ny) + " nodes got " + std::to_string(z.size())
                                     + " values."));
      for (const double v : z)
        AssertThrow(std::isfinite(v) || (with_gaps && std::isnan(v)),
                    dealii::ExcMessage("An elevation grid holds a value that is not finite "
                                       "(no-data must be handled before the grid is made)."));
    }



    ElevationGrid
    ElevationGrid::from_function(const std::function<double(double, double)> &function,
                                 const dealii::Point<2>                      &lower,
                                 const dealii::Point<2>                      &upper,
                                 const unsigned int                           nx,
                                 const unsigned int                           ny)
    {
      AssertThrow(nx >= 2 && ny >= 2 && upper[0] > lower[0] && upper[1] > lower[1],
                  dealii::ExcMessage("An elevation grid needs at least 2 x 2 nodes over a "
                                     "box of positive size."));
      const double        dx = (upper[0] - lower[0]) / (nx - 1);
      const double        dy = (upper[1] - lower[1]) / (ny - 1);
      std::vector<double> values(static_cast<std::size_t>(nx) * ny);
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          values[j * nx + i] = function(lower[0] + i * dx, lower[1] + j * dy);
      return ElevationGrid(lower, dx, dy, nx, ny, std::move(values));
    }



    bool
    ElevationGrid::contains(const dealii::Point<2> &p) const
    {
      const dealii::Point<2> top = upper();
      const double           tx = 1e-12 * dx, ty = 1e-12 * dy;
      return p[0] >= origin[0] - tx && p[0] <= top[0] + tx && p[1] >= origin[1] - ty
             && p[1] <= top[1] + ty;
    }
  } // namespace terrain
} // namespace slidewave
