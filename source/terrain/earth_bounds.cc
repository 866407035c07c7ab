#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/earth_bounds.h>

namespace slidewave
{
  namespace terrain
  {
    std::string
    elevation_bounds_text()
    {
      return "elevations between " + to_string(lowest_elevation) + " m and "
             + to_string(highest_elevation)
             + " m (the Earth's lowest and highest points are about -10935 m and 8849 m)";
    }



    void
    check_elevation(const std::string &parameter,
                    const std::string &value,
                    const double       x,
                    const double       y,
                    const double       z)
    {
      if (!(z >= lowest_elevation && z <= highest_elevation))
        throw InputError(parameter,
                         value,
                         elevation_bounds_text() + ": at (" + to_string(x) + ", " + to_string(y)
                           + ") it is " + to_string(z) + " m");
    }
  } // namespace terrain
} // namespace slidewave
