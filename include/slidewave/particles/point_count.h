#ifndef slidewave_particles_point_count_h
#define slidewave_particles_point_count_h

#include <deal.II/base/point.h>
#include <slidewave/particles/material_region.h>
#include <vector>

namespace slidewave
{
  namespace particles
  {
    /**
     * How many material points @p regions will hold at most on the grid [@p lower_left,
     * @p upper_right] of square cells of @p cell_size with @p per_direction^2 points per
     * cell, before they are made: the cells under each region's bounding box (the whole
     * grid for a region whose polygon is read later from a file), at most the whole grid.
     * An upper bound for the memory estimate (core::MemoryEstimate).
     */
    double
    point_count_bound(const std::vector<MaterialRegion> &regions,
                      const dealii::Point<2>            &lower_left,
                      const dealii::Point<2>            &upper_right,
                      double                             cell_size,
                      unsigned int                       per_direction);

    /** The number of cells of the grid [@p lower_left, @p upper_right] of @p cell_size. */
    double
    grid_cell_count(const dealii::Point<2> &lower_left,
                    const dealii::Point<2> &upper_right,
                    double                  cell_size);
  } // namespace particles
} // namespace slidewave

#endif
