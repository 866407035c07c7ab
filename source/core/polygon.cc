#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/polygon.h>

namespace slidewave
{
  namespace core
  {
    std::vector<dealii::Point<2>>
    parse_polygon(const std::string &parameter,
                  const std::string &text,
                  const std::string &unit,
                  const std::string &noun)
    {
      const std::string form    = noun + " 'x1, y1; x2, y2; ...'";
      const std::string allowed = form + (unit.empty() ? std::string() : " [" + unit + "]");
      std::vector<dealii::Point<2>> ring;
      for (const auto &vertex : dealii::Utilities::split_string_list(text, ';'))
        {
          const auto v = parse_number_list(parameter, vertex, allowed);
          if (v.size() != 2)
            throw InputError(parameter, text, form + " (two numbers each)");
          ring.emplace_back(v[0], v[1]);
        }
      return ring;
    }



    double
    signed_area(const std::vector<dealii::Point<2>> &ring)
    {
      double twice_area = 0.;
      for (unsigned int i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
        twice_area += ring[j][0] * ring[i][1] - ring[i][0] * ring[j][1];
      return 0.5 * twice_area;
    }



    std::pair<dealii::Point<2>, dealii::Point<2>>
    bounding_box(const std::vector<dealii::Point<2>> &ring)
    {
      dealii::Point<2> lower = ring[0], upper = ring[0];
      for (const auto &p : ring)
        for (unsigned int d = 0; d < 2; ++d)
          {
            lower[d] = std::min(lower[d], p[d]);
            upper[d] = std::max(upper[d], p[d]);
          }
      return {lower, upper};
    }



    PolygonSide
    side_of(const std::vector<dealii::Point<2>> &ring,
            const dealii::Point<2>              &p,
            const EdgeTest                       edge_test,
            const double                         tolerance)
    {
      bool               inside = false;
      const unsigned int n      = ring.size();
      for (unsigned int i = 0, j = n - 1; i < n; j = i++)
        {
          const dealii::Point<2>    &a = ring[i], &b = ring[j];
          const dealii::Tensor<1, 2> edge = b - a;
          if (edge_test == EdgeTest::distance)
            {
              // The distance to the closest point of the segment.
              const double t
                = std::clamp((p - a) * edge / std::max(edge.norm_square(), 1e-300), 0., 1.);
              if (p.distance(a + t * edge) <= tolerance)
                return PolygonSide::on_edge;
            }
          else
            {
              // On the line a-b, within the segment's box.
              const double cross = edge[0] * (p[1] - a[1]) - edge[1] * (p[0] - a[0]);
              if (std::abs(cross) <= tolerance * (a.distance(b) + 1.)
                  && p[0] >= std::min(a[0], b[0]) - tolerance
                  && p[0] <= std::max(a[0], b[0]) + tolerance
                  && p[1] >= std::min(a[1], b[1]) - tolerance
                  && p[1] <= std::max(a[1], b[1]) + tolerance)
                return PolygonSide::on_edge;
            }
          // Does the ray from p towards +x cross the edge?
          if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < a[0] + edge[0] * (p[1] - a[1]) / edge[1])
            inside = !inside;
        }
      return inside ? PolygonSide::inside : PolygonSide::outside;
    }
  } // namespace core
} // namespace slidewave
