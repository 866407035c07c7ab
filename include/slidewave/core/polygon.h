#ifndef slidewave_core_polygon_h
#define slidewave_core_polygon_h

#include <deal.II/base/point.h>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace core
  {
    // Polygons in the plane, as the scenes give them: a ring of vertices in order around
    // it (either way), closed implicitly (the last vertex joins the first). Shared by the
    // rigid solids (grid::RigidSolid) and the material regions (particles::MaterialRegion).

    /** Where a point lies with respect to a polygon (side_of()). */
    enum class PolygonSide
    {
      outside,
      inside,
      on_edge
    };

    /** How side_of() decides that a point lies on an edge a-b. */
    enum class EdgeTest
    {
      /** Within the tolerance (a distance [m]) of the closest point of the segment a-b;
       *  with tolerance 0 only a point the projection meets exactly (the rigid solids,
       *  grid::RigidSolid::contains()). */
      distance,
      /** On the line a-b to a relative tolerance, |(b - a) x (p - a)| <= tolerance
       *  (|b - a| + 1), and within the tolerance of the segment's bounding box (the
       *  material regions, with tolerance 1e-12). */
      collinear
    };

    /**
     * The vertices 'x1, y1; x2, y2; ...' of @p text, the value of @p parameter. Throws an
     * InputError naming @p parameter when a vertex is not a list of finite numbers
     * ("vertices 'x1, y1; x2, y2; ...'", followed by " [@p unit]" unless @p unit is empty)
     * or not two of them ("vertices 'x1, y1; x2, y2; ...' (two numbers each)"). How many
     * vertices are needed is the caller's to check. @p noun names the items in the messages
     * ("points" for a list of probes).
     */
    std::vector<dealii::Point<2>>
    parse_polygon(const std::string &parameter,
                  const std::string &text,
                  const std::string &unit,
                  const std::string &noun = "vertices");

    /** The signed area of @p ring (the shoelace formula; positive counter-clockwise); 0
     *  with fewer than three vertices. */
    double
    signed_area(const std::vector<dealii::Point<2>> &ring);

    /** The lower left and upper right corners of the box around @p ring (not empty). */
    std::pair<dealii::Point<2>, dealii::Point<2>>
    bounding_box(const std::vector<dealii::Point<2>> &ring);

    /**
     * Where @p p lies with respect to @p ring: on an edge (as @p edge_test decides, with
     * @p tolerance), otherwise inside or outside by the even-odd rule (a ray towards +x).
     * The edges are visited in order from the one joining the last vertex to the first;
     * the first edge found to hold @p p decides.
     */
    PolygonSide
    side_of(const std::vector<dealii::Point<2>> &ring,
            const dealii::Point<2>              &p,
            EdgeTest                             edge_test,
            double                               tolerance);
  } // namespace core
} // namespace slidewave

#endif
