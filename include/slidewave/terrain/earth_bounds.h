#ifndef slidewave_terrain_earth_bounds_h
#define slidewave_terrain_earth_bounds_h

#include <string>

namespace slidewave
{
  namespace terrain
  {
    /**
     * @name What the Earth allows
     * Values read from a file or an expression outside these bounds are refused (issue 29:
     * a DEM with an elevation of 1e300, a finite number, ran and lost every column in its
     * first step). The bounds are wide on purpose: they catch an undeclared no-data value
     * (-3.4e38, -9999 under the sea floor), a file in the wrong unit by orders of magnitude
     * or garbage, not a legitimate terrain.
     * @{
     */

    /** The lowest elevation [m]: the Challenger Deep is about -10,935 m. */
    constexpr double lowest_elevation = -11000.;

    /** The highest elevation [m]: Mount Everest is 8,849 m. */
    constexpr double highest_elevation = 9000.;

    /** The deepest release [m], vertical: the largest known landslides (Seymareh, about
     *  44 km^3; Heart Mountain) moved masses a few hundred metres thick; a depth-averaged
     *  model needs the depth small against the flow's length, which 1000 m no longer is
     *  at any scale a DEM resolves. */
    constexpr double largest_release_depth = 1000.;

    /** "elevations between -11000 m and 9000 m (the Earth's lowest and highest points,
     *  about -10935 m and 8849 m)": the bounds as messages state them. */
    std::string
    elevation_bounds_text();

    /** Refuses an elevation @p z at (@p x, @p y) outside [lowest_elevation,
     *  highest_elevation] (or not finite): an InputError(@p parameter, @p value, ...)
     *  naming the point and the bounds. */
    void
    check_elevation(const std::string &parameter,
                    const std::string &value,
                    double             x,
                    double             y,
                    double             z);

    /** @} */
  } // namespace terrain
} // namespace slidewave

#endif
