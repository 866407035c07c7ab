#ifndef slidewave_fluid_flow_boundaries_h
#define slidewave_fluid_flow_boundaries_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <string>

namespace slidewave
{
  namespace fluid
  {
    /** What a side of the tank does to the flow. */
    enum class FlowBoundary
    {
      no_slip,   ///< u = 0
      free_slip, ///< u . n = 0, no shear
      open,      ///< traction free: the ambient pressure (0), water and air may leave
      inflow     ///< u prescribed ('Inflow velocity'), water below 'Inflow water level'
    };

    /**
     * The sides of the tank (subsection "Boundary conditions"): what each does, the
     * velocity and the water level of the inflow sides, and the backflow stabilization of
     * the open sides (doc/free-surface-flow.md, "Boundaries").
     */
    struct FlowBoundaries
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks the entries (the handler inside "Boundary conditions");
       *  @p section names the enclosing subsection in messages. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &section);

      /** The side @p id (the grid's boundary ids: left 0, right 1, bottom 2, top 3). */
      FlowBoundary
      operator[](const unsigned int id) const
      {
        return sides[id];
      }

      /** Whether some side is of type @p type. */
      bool
      any(const FlowBoundary type) const
      {
        for (const auto side : sides)
          if (side == type)
            return true;
        return false;
      }

      /** No side open and none an inflow: the pressure level is pinned at a corner. */
      bool
      closed() const
      {
        return !any(FlowBoundary::open) && !any(FlowBoundary::inflow);
      }

      /** The water fraction of what enters at height @p y: the equilibrium profile of
       *  the phase field, 1 / (1 + exp(-(level - y) / epsilon)). */
      double
      inflow_phase(const double y, const double epsilon) const;

      std::array<FlowBoundary, 4> sides{{FlowBoundary::free_slip,
                                         FlowBoundary::free_slip,
                                         FlowBoundary::free_slip,
                                         FlowBoundary::open}};
      /** u(x, y, t) of the inflow sides: "u_x; u_y" in muparser syntax. */
      std::string inflow_velocity = "0; 0";
      /** Water enters below this elevation [m], air above it. */
      double inflow_level = 0.;
      /** beta of the backflow stabilization of the open sides (0: none). */
      double backflow = 1.;
    };
  } // namespace fluid
} // namespace slidewave

#endif
