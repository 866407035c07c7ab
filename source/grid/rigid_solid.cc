#include <algorithm>
#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/core/polygon.h>
#include <slidewave/grid/rigid_bodies.h>
#include <slidewave/grid/rigid_solid.h>
#include <sstream>

namespace slidewave
{
  namespace grid
  {
    void
    RigidSolid::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.declare_entry("Polygon",
                        "",
                        dealii::Patterns::Anything(),
                        "Of a 'solid': vertices 'x1, y1; x2, y2; ...' [m], at least three, in "
                        "order around it.");
    }



    void
    RigidSolid::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      this->path             = path;
      const std::string text = prm.get("Polygon");
      polygon                = core::parse_polygon(path + "/Polygon", text, "m");
      if (polygon.size() < 3 || !(std::abs(core::signed_area(polygon)) > 0.))
        throw InputError(path + "/Polygon",
                         text,
                         "at least three vertices enclosing an area (the solid of 'Type = "
                         "solid')");
      release_time = parse_release_time(prm, path);
    }



    void
    RigidSolid::check_in_grid(const dealii::Point<2> &lower_left,
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
    RigidSolid::contains(const dealii::Point<2> &x, const double tolerance) const
    {
      // Inside (even-odd rule), or within the tolerance (a distance) of an edge.
      return core::side_of(polygon, x, core::EdgeTest::distance, tolerance)
             != core::PolygonSide::outside;
    }



    bool
    inside_a_solid(const std::vector<RigidSolid> &solids, const dealii::Point<2> &x)
    {
      for (const auto &solid : solids)
        if (solid.contains(x, 0.))
          return true;
      return false;
    }
  } // namespace grid
} // namespace slidewave
