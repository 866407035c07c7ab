#ifndef slidewave_terrain_elevation_table_h
#define slidewave_terrain_elevation_table_h

#include <slidewave/terrain/elevation_grid.h>
#include <string>

namespace slidewave
{
  namespace terrain
  {
    /**
     * A terrain given as a grid of values: a CSV file of rows x,y,z (any order, '#'
     * comments and a header allowed) whose points form a complete regular lattice, every
     * node once, at least 2 x 2. Anything else (a missing node, a node twice, unequal
     * spacings) is an InputError naming @p parameter, the file and the problem.
     */
    ElevationGrid
    read_elevation_table(const std::string &parameter, const std::string &filename);
  } // namespace terrain
} // namespace slidewave

#endif
