#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
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
          for (const auto &vertex : dealii::Utilities::split_string_list(text, ';'))
            {
              const auto v = parse_number_list(path + "/Polygon",
                                               vertex,
                                               "vertices 'x1, y1; x2, y2; ...' [m]");
              if (v.size() != 2)
                throw InputError(path + "/Polygon",
                                 text,
                                 "vertices 'x1, y1; x2, y2; ...' (two numbers each)");
              polygon.emplace_back(v[0], v[1]);
            }
          double twice_area = 0.;
          for (unsigned int i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
            twice_area += polygon[j][0] * polygon[i][1] - polygon[i][0] * polygon[j][1];
          if (polygon.size() < 3 || !(std::abs(twice_area) > 0.))
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
      double           twice_area = 0.;
      dealii::Point<2> low = polygon[0], high = polygon[0];
      for (unsigned int i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
        {
          twice_area += polygon[j][0] * polygon[i][1] - polygon[i][0] * polygon[j][1];
          for (unsigned int d = 0; d < 2; ++d)
            {
              low[d]  = std::min(low[d], polygon[i][d]);
              high[d] = std::max(high[d], polygon[i][d]);
            }
        }
      bool inside = true;
      for (unsigned int d = 0; d < 2; ++d)
        inside = inside
                 && std::min(high[d], upper_right[d]) - std::max(low[d], lower_left[d])
                      >= cell_size * (1. - 1e-9);
      std::ostringstream area;
      area << cell_size * cell_size;
      if (!(0.5 * std::abs(twice_area) >= cell_size * cell_size * (1. - 1e-9)) || !inside)
        throw InputError(path + "/Polygon",
                         text.str(),
                         "a solid of at least one cell's area (h^2 = " + area.str()
                           + " m^2) reaching a cell into the grid in each direction (a "
                             "smaller one would hold no node)");
    }



    bool
    RigidWall::contains(const dealii::Point<2> &x, const double tolerance) const
    {
      if (is_solid())
        {
          // Inside (even-odd rule), or within the tolerance of an edge.
          bool inside = false;
          for (unsigned int i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
            {
              const dealii::Point<2>    &a = polygon[i], &b = polygon[j];
              const dealii::Tensor<1, 2> edge = b - a;
              const double               t
                = std::clamp((x - a) * edge / std::max(edge.norm_square(), 1e-300), 0., 1.);
              if (x.distance(a + t * edge) <= tolerance)
                return true;
              if ((a[1] > x[1]) != (b[1] > x[1]) && x[0] < a[0] + edge[0] * (x[1] - a[1]) / edge[1])
                inside = !inside;
            }
          return inside;
        }
      const unsigned int n = normal_component(), t = 1 - n;
      return std::abs(x[n] - start[n]) <= tolerance
             && x[t] >= std::min(start[t], end[t]) - tolerance
             && x[t] <= std::max(start[t], end[t]) + tolerance;
    }
  } // namespace grid
} // namespace slidewave
