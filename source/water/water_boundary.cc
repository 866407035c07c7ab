#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/water/water_boundary.h>

namespace slidewave
{
  namespace water
  {
    void
    WaterBoundary::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Type",
                        "wall",
                        Selection("wall|transmissive|discharge|depth"),
                        "'wall': closed, no flow through. 'transmissive': open, waves leave. "
                        "'discharge': given discharge q(t) [m^2/s], positive in +x. 'depth': "
                        "given depth h(t) [m].");
      prm.declare_entry("Value",
                        "0",
                        Anything(),
                        "For 'discharge' and 'depth': the prescribed value as an expression "
                        "of t (e.g. '0.5' or '0.1*sin(t)'). Ignored when 'Time series file' "
                        "is set.");
      prm.declare_entry("Time series file",
                        "",
                        Anything(),
                        "For 'discharge' and 'depth': a CSV table t,value interpolated "
                        "linearly in time (constant beyond its ends), relative to the scene "
                        "file.");
    }



    WaterBoundary::WaterBoundary(const Type type)
      : boundary_type(type)
    {
    }



    void
    WaterBoundary::parse_parameters(dealii::ParameterHandler &prm,
                                    const std::string        &path,
                                    const SceneParameters    &scene)
    {
      const std::string type = prm.get("Type");
      if (type == "wall")
        boundary_type = Type::wall;
      else if (type == "transmissive")
        boundary_type = Type::transmissive;
      else if (type == "discharge")
        boundary_type = Type::discharge;
      else
        boundary_type = Type::depth;

      if (boundary_type == Type::discharge || boundary_type == Type::depth)
        {
          const std::string file = prm.get("Time series file");
          if (!file.empty())
            series
              = std::make_shared<Table1D>(path + "/Time series file", scene.resolve_path(file));
          else
            expression = std::make_shared<ParsedExpression>(path + "/Value", prm.get("Value"));
          if (boundary_type == Type::depth && prescribed_value(0.) < 0.)
            throw InputError(path + "/Value", prm.get("Value"), "a depth >= 0");
        }
    }



    double
    WaterBoundary::prescribed_value(const double t) const
    {
      return series ? series->value(t) : expression->value(0., t);
    }



    void
    WaterBoundary::ghost_state(const double h_inside,
                               const double u_inside,
                               const double t,
                               const double gravity,
                               const double dry_depth,
                               const bool   left_end,
                               double      &h_ghost,
                               double      &u_ghost) const
    {
      switch (boundary_type)
        {
          case Type::wall:
            h_ghost = h_inside;
            u_ghost = -u_inside;
            return;
          case Type::transmissive:
            h_ghost = h_inside;
            u_ghost = u_inside;
            return;
            case Type::discharge: {
              const double q = prescribed_value(t);
              h_ghost        = h_inside > dry_depth ? h_inside : std::cbrt(q * q / gravity);
              u_ghost        = h_ghost > dry_depth ? q / h_ghost : 0.;
              return;
            }
            case Type::depth: {
              h_ghost = std::max(prescribed_value(t), 0.);
              if (h_inside <= dry_depth)
                {
                  u_ghost = 0.;
                  return;
                }
              // The characteristic leaving the domain carries u - 2c (left end) or
              // u + 2c (right end) unchanged to the ghost state.
              const double dc = std::sqrt(gravity * h_ghost) - std::sqrt(gravity * h_inside);
              u_ghost         = left_end ? u_inside + 2. * dc : u_inside - 2. * dc;
              return;
            }
        }
    }
  } // namespace water
} // namespace slidewave
