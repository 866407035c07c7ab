#ifndef slidewave_grid_rigid_wall_h
#define slidewave_grid_rigid_wall_h

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
     * A rigid wall inside (or on the edge of) the background grid: a horizontal or
     * vertical segment on grid lines whose nodes are held, in the normal direction
     * ('roller', free slip) or in both ('fixed', no slip). A wall with a release time is a
     * removable support: it holds the material until then and is gone afterwards (the
     * gate of a column collapse, the face support of a tunnel). Without one it is
     * permanent (a tunnel lining, a step in the bed).
     *
     * A 'solid' is a rigid body of any shape, a polygon: every node inside it or on its
     * edges is held in both directions (no slip), so that the grid's held nodes follow the
     * body's outline to a cell (a staircase; an inclined plane across the cells, paper
     * 002, §4.3). In granular water the water's velocity is held at the same nodes.
     */
    struct RigidWall
    {
      /** Subsections "Rigid wall 1" ... a scene may declare. */
      static constexpr unsigned int max_walls = 4;

      enum class Condition
      {
        roller,
        fixed
      };

      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads one "Rigid wall N"; returns false when its Type is 'none'. */
      bool
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** A solid must hold nodes of the grid [@p lower_left, @p upper_right] of cells
       *  @p cell_size: an area of at least one cell inside the grid; and the grid must not
       *  adapt (@p adaptive: a coarse cell could step over a thin solid, and the two
       *  phases would hold a hanging node differently). Throws an InputError naming the
       *  parameter otherwise. */
      void
      check_solid_in_grid(const dealii::Point<2> &lower_left,
                          const dealii::Point<2> &upper_right,
                          double                  cell_size,
                          bool                    adaptive) const;

      /** Whether @p x lies on the segment, or for a solid inside the polygon or on its
       *  edges (within @p tolerance). */
      bool
      contains(const dealii::Point<2> &x, double tolerance) const;

      /** 0 for a vertical wall (it holds v_x), 1 for a horizontal one (v_y); a solid
       *  holds both (its condition is 'fixed'). */
      unsigned int
      normal_component() const
      {
        return start[0] == end[0] ? 0 : 1;
      }

      bool
      is_solid() const
      {
        return !polygon.empty();
      }

      Condition        condition = Condition::roller;
      dealii::Point<2> start, end;
      /** A solid's outline (at least three vertices, in order; empty for a segment). */
      std::vector<dealii::Point<2>> polygon;
      /** Where it was read ("<section>/Rigid wall N"), for messages. */
      std::string path;
      /** The wall holds while t < release_time. */
      double release_time = std::numeric_limits<double>::infinity();
    };

    /** Whether @p x lies inside one of the solids among @p walls or on its edges (exactly:
     *  RigidWall::contains() with tolerance 0); segments are ignored. No material point is
     *  created there. */
    bool
    inside_a_solid(const std::vector<RigidWall> &walls, const dealii::Point<2> &x);
  } // namespace grid
} // namespace slidewave

#endif
