#ifndef slidewave_grid_rigid_solid_h
#define slidewave_grid_rigid_solid_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <limits>
#include <string>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * A rigid solid inside (or across the edge of) the background grid: a body of any
     * shape, a polygon, whose every node inside it or on its edges is held in both
     * directions (no slip), so that the grid's held nodes follow the body's outline to a
     * cell (a staircase; an inclined plane across the cells, paper 002, §4.3). In granular
     * water the water's velocity is held at the same nodes and no point is created inside
     * it. Read from a "Rigid wall N" subsection with 'Type = solid' (rigid_bodies.h); the
     * segments of the other types are RigidWall.
     */
    struct RigidSolid
    {
      /** Declares the solid's own entry, 'Polygon', in a "Rigid wall N" subsection (the
       *  subsection's other entries: declare_rigid_body_parameters()). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads the polygon and the release time of the "Rigid wall N" at @p path (of
       *  'Type = solid'); throws an InputError naming the parameter if they are invalid. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** A solid must hold nodes of the grid [@p lower_left, @p upper_right] of cells
       *  @p cell_size: an area of at least one cell inside the grid; and the grid must not
       *  adapt (@p adaptive: a coarse cell could step over a thin solid, and the two
       *  phases would hold a hanging node differently). Throws an InputError naming the
       *  parameter otherwise. */
      void
      check_in_grid(const dealii::Point<2> &lower_left,
                    const dealii::Point<2> &upper_right,
                    double                  cell_size,
                    bool                    adaptive) const;

      /** Whether @p x lies inside the polygon (even-odd rule) or within @p tolerance (a
       *  distance) of one of its edges. */
      bool
      contains(const dealii::Point<2> &x, double tolerance) const;

      /** The outline (at least three vertices enclosing an area, in order around it). */
      std::vector<dealii::Point<2>> polygon;
      /** Where it was read ("<section>/Rigid wall N"), for messages. */
      std::string path;
      /** The solid holds while t < release_time. */
      double release_time = std::numeric_limits<double>::infinity();
    };

    /** Whether @p x lies inside one of @p solids or on its edges (exactly:
     *  RigidSolid::contains() with tolerance 0). No material point is created there. */
    bool
    inside_a_solid(const std::vector<RigidSolid> &solids, const dealii::Point<2> &x);
  } // namespace grid
} // namespace slidewave

#endif
