#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
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
      prm.declare_entry("Type",
                        "none",
                        Selection("none|roller|fixed"),
                        "'none': this wall is not used. 'roller': the nodes on the wall keep "
                        "zero normal velocity (free slip). 'fixed': zero velocity (no slip).");
      prm.declare_entry("From",
                        "0, 0",
                        Anything(),
                        "One end 'x, y' of the wall [m]; the wall is horizontal or vertical "
                        "and lies on grid lines.");
      prm.declare_entry("To", "0, 1", Anything(), "The other end 'x, y' [m].");
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
      condition = type == "fixed" ? Condition::fixed : Condition::roller;
      start     = parse_point(path + "/From", prm.get("From"));
      end       = parse_point(path + "/To", prm.get("To"));
      if (start.distance(end) == 0. || (start[0] != end[0] && start[1] != end[1]))
        throw InputError(path + "/To",
                         prm.get("To"),
                         "a point other than 'From' on the same vertical or horizontal "
                         "line (walls are axis-aligned)");
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
