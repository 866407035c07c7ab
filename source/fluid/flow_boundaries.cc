#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/fluid/flow_boundaries.h>
#include <slidewave/fluid/phase_profile.h>

namespace slidewave
{
  namespace fluid
  {
    namespace
    {
      FlowBoundary
      flow_boundary(const std::string &name)
      {
        return name == "no slip" ? FlowBoundary::no_slip :
               name == "open"    ? FlowBoundary::open :
               name == "inflow"  ? FlowBoundary::inflow :
                                   FlowBoundary::free_slip;
      }
    } // namespace



    void
    FlowBoundaries::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      const std::string help
        = "'no slip' (u = 0), 'free slip' (no flow through the side, no shear), 'open' "
          "(traction free at the ambient pressure 0: water and air may leave, and air may "
          "enter) or 'inflow' (u = 'Inflow velocity', water below 'Inflow water level' and "
          "air above it enter). A tank with no open or inflow side is closed: its pressure "
          "level is set to 0 at the lower left corner.";
      const std::string types = "no slip|free slip|open|inflow";
      prm.declare_entry("Left", "free slip", Selection(types), help);
      prm.declare_entry("Right", "free slip", Selection(types), help);
      prm.declare_entry("Bottom", "free slip", Selection(types), help);
      prm.declare_entry("Top", "open", Selection(types), help);
      prm.declare_entry("Inflow velocity",
                        "0; 0",
                        Anything(),
                        "u_x; u_y [m/s] on the inflow sides: expressions of x, y and t "
                        "(muparser syntax), imposed at every node of those sides.");
      prm.declare_entry("Inflow water level",
                        "0",
                        Double(),
                        "y [m] below which what enters through an inflow side is water "
                        "(above it: air), with the phase field's equilibrium profile across "
                        "it.");
      prm.declare_entry("Backflow stabilization",
                        "1",
                        Double(0., 10.),
                        "beta of the open sides' backflow term, a traction beta rho "
                        "min(u.n, 0) u that damps what flows back in (Esmaily Moghadam et "
                        "al. 2011); 0: none.");
    }



    void
    FlowBoundaries::parse_parameters(dealii::ParameterHandler &prm, const std::string &section)
    {
      sides           = {{flow_boundary(prm.get("Left")),
                          flow_boundary(prm.get("Right")),
                          flow_boundary(prm.get("Bottom")),
                          flow_boundary(prm.get("Top"))}};
      inflow_velocity = prm.get("Inflow velocity");
      inflow_level    = prm.get_double("Inflow water level");
      backflow        = prm.get_double("Backflow stabilization");
      dealii::FunctionParser<2> function(2);
      initialize_parser(function,
                        "x,y,t",
                        inflow_velocity,
                        true,
                        section + "/Boundary conditions/Inflow velocity",
                        "two expressions 'u_x; u_y' of x, y and t in muparser syntax");
    }



    double
    FlowBoundaries::inflow_phase(const double y, const double epsilon) const
    {
      return equilibrium_phase(inflow_level - y, epsilon);
    }
  } // namespace fluid
} // namespace slidewave
