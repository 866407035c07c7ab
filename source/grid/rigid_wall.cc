#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/polygon.h>
#include <slidewave/grid/rigid_wall.h>
#include <sstream>

namespace slidewave
{
  namespace grid
  {
    namespace
    {
      dealii::Point<2>
      parse_point(const std::string &parameter, const std::string &text)
      {
        const auto xy = parse_number_list(parameter, text, "a point 'x, y' [m]", 2);
        return dealii::Point<2>(xy[0], xy[1]);
      }
    } // namespace



    void
    RigidWall::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Type",
                        "none",
                        Selection("none|roller|fixed|solid"),
                        "'none': this wall is not used. 'roller': the nodes on the wall keep "
                        "zero normal velocity (free slip). 'fixed': zero velocity (no slip). "
                        "'solid': a rigid body, the polygon 'Polygon'; every node inside it or "
                        "on its edges keeps zero velocity (no slip; an inclined plane across "
                        "the cells becomes a staircase of held nodes). In granular water the "
                        "water's velocity is held at the same nodes, and no point is created "
                        "inside the solid.");
      prm.declare_entry("From",
                        "0, 0",
                        Anything(),
                        "One end 'x, y' of the wall [m]; the wall is horizontal or vertical "
                        "and lies on grid lines.");
      prm.declare_entry("To", "0, 1", Anything(), "The other end 'x, y' [m].");
      prm.declare_entry("Polygon",
                        "",
                        Anything(),
                        "Of a 'solid': vertices 'x1, y1; x2, y2; ...' [m], at least three, in "
                        "order around it.");
      prm.declare_entry("Release time",
                        "never",
                        Anything(),
                        "'never' for a permanent wall, or the time [s] at which this "
                        "support is removed (it holds while t < release time; it also holds "
                        "during gravity loading).");
    }



    bool
    RigidWall::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      const std::string type = prm.get("Type");
      if (type == "none")
        return false;
      condition  = type == "roller" ? Condition::roller : Condition::fixed;
      this->path = path;
      polygon.clear();
      if (type == "solid")
        {
          const std::string text = prm.get("Polygon");
          polygon                = core::parse_polygon(path + "/Polygon", text, "m");
          if (polygon.size() < 3 || !(std::abs(core::signed_area(polygon)) > 0.))
            throw InputError(path + "/Polygon",
                             text,
                             "at least three vertices enclosing an area (the solid of 'Type = "
                             "solid')");
        }
      else
        {
          start = parse_point(path + "/From", prm.get("From"));
          end   = parse_point(path + "/To", prm.get("To"));
          if (start.distance(end) == 0. || (start[0] != end[0] && start[1] != end[1]))
            throw InputError(path + "/To",
                             prm.get("To"),
                             "a point other than 'From' on the same vertical or horizontal "
                             "line (walls are axis-aligned)");
        }
      const std::string release = dealii::Utilities::trim(prm.get("Release time"));
      if (release == "never")
        release_time = std::numeric_limits<double>::infinity();
      else
        {
          bool ok = true;
          try
            {
              std::size_t used = 0;
              release_time     = std::stod(release, &used);
              ok               = used == release.size() && std::isfinite(release_time);
            }
          catch (const std::exception &)
            {
              ok = false;
            }
          if (!ok)
            throw InputError(path + "/Release time", release, "'never' or a time [s]");
        }
      return true;
    }



    void
    RigidWall::check_solid_in_grid(const dealii::Point<2> &lower_left,
                                   const dealii::Point<2> &upper_right,
                                   const double            cell_size,
                                   const bool              adaptive) const
    {
      std::ostringstream text;
      for (unsigned int i = 0; i < polygon.size(); ++i)
        text << (i > 0 ? "; " : "") << polygon[i][0] << ", " << polygon[i][1];
      if (adaptive)
        throw InputError(path + "/Type",
                         "solid",
                         "none, roller or fixed on an adaptive grid (a coarse cell could step "
                         "over a thin solid; the solid's cells are not kept fine)");
      // The area inside the grid, by clipping is not needed: a solid of one cell's area
      // whose box overlaps the grid by a cell in each direction holds nodes.
      const auto [low, high] = core::bounding_box(polygon);
      bool inside            = true;
      for (unsigned int d = 0; d < 2; ++d)
        inside = inside
                 && std::min(high[d], upper_right[d]) - std::max(low[d], lower_left[d])
                      >= cell_size * (1. - 1e-9);
      std::ostringstream area;
      area << cell_size * cell_size;
      if (!(std::abs(core::signed_area(polygon)) >= cell_size * cell_size * (1. - 1e-9)) || !inside)
        throw InputError(path + "/Polygon",
                         text.str(),
                         "a solid of at least one cell's area (h^2 = " + area.str()
                           + " m^2) reaching a cell into the grid in each direction (a "
                             "smaller one would hold no node)");
    }



    bool
    RigidWall::contains(const dealii::Point<2> &x, const double tolerance) const
    {
      // A solid: inside (even-odd rule), or within the tolerance (a distance) of an edge.
      if (is_solid())
        return core::side_of(polygon, x, core::EdgeTest::distance, tolerance)
               != core::PolygonSide::outside;
      const unsigned int n = normal_component(), t = 1 - n;
      return std::abs(x[n] - start[n]) <= tolerance
             && x[t] >= std::min(start[t], end[t]) - tolerance
             && x[t] <= std::max(start[t], end[t]) + tolerance;
    }



    bool
    inside_a_solid(const std::vector<RigidWall> &walls, const dealii::Point<2> &x)
    {
      for (const auto &wall : walls)
        if (wall.is_solid() && wall.contains(x, 0.))
          return true;
      return false;
    }
  } // namespace grid
} // namespace slidewave
