#include <algorithm>
#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/grid/rigid_bodies.h>
#include <slidewave/grid/rigid_wall.h>

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
      prm.declare_entry("From",
                        "0, 0",
                        Anything(),
                        "One end 'x, y' of the wall [m]; the wall is horizontal or vertical "
                        "and lies on grid lines.");
      prm.declare_entry("To", "0, 1", Anything(), "The other end 'x, y' [m].");
    }



    void
    RigidWall::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      condition = prm.get("Type") == "roller" ? Condition::roller : Condition::fixed;
      start     = parse_point(path + "/From", prm.get("From"));
      end       = parse_point(path + "/To", prm.get("To"));
      if (start.distance(end) == 0. || (start[0] != end[0] && start[1] != end[1]))
        throw InputError(path + "/To",
                         prm.get("To"),
                         "a point other than 'From' on the same vertical or horizontal "
                         "line (walls are axis-aligned)");
      release_time = parse_release_time(prm, path);
    }



    bool
    RigidWall::contains(const dealii::Point<2> &x, const double tolerance) const
    {
      const unsigned int n = normal_component(), t = 1 - n;
      return std::abs(x[n] - start[n]) <= tolerance
             && x[t] >= std::min(start[t], end[t]) - tolerance
             && x[t] <= std::max(start[t], end[t]) + tolerance;
    }
  } // namespace grid
} // namespace slidewave
