#ifndef slidewave_grid_rigid_wall_h
#define slidewave_grid_rigid_wall_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <limits>
#include <string>

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
     * permanent (a tunnel lining, a step in the bed). Read from a "Rigid wall N"
     * subsection of 'Type = roller' or 'fixed' (rigid_bodies.h); a body of any shape,
     * 'Type = solid', is a RigidSolid.
     */
    struct RigidWall
    {
      enum class Condition
      {
        roller,
        fixed
      };

      /** Declares the segment's own entries, 'From' and 'To', in a "Rigid wall N"
       *  subsection (the subsection's other entries: declare_rigid_body_parameters()). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads the condition (the Type, 'roller' or 'fixed'), the ends and the release
       *  time of the "Rigid wall N" at @p path; throws an InputError naming the parameter
       *  if they are invalid (the ends must differ on a vertical or horizontal line). */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** Whether @p x lies on the segment (within @p tolerance). */
      bool
      contains(const dealii::Point<2> &x, double tolerance) const;

      /** 0 for a vertical wall (it holds v_x), 1 for a horizontal one (v_y). */
      unsigned int
      normal_component() const
      {
        return start[0] == end[0] ? 0 : 1;
      }

      Condition        condition = Condition::roller;
      dealii::Point<2> start, end;
      /** The wall holds while t < release_time. */
      double release_time = std::numeric_limits<double>::infinity();
    };
  } // namespace grid
} // namespace slidewave

#endif
