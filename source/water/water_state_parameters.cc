#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/water/water_state_parameters.h>

namespace slidewave
{
  namespace water
  {
    void
    BedElevation::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Type",
                        "function",
                        Selection("function|table"),
                        "'function': B(x) from 'Function expression'. 'table': from the "
                        "CSV file 'Table file' (x,B), interpolated linearly. In a coupled "
                        "scene this is the fixed terrain; the bed is the higher of it and "
                        "the soil surface.");
      prm.declare_entry("Function expression",
                        "0",
                        Anything(),
                        "Bed elevation B(x) [m], an expression of x (and of t with "
                        "'Time dependent').");
      prm.declare_entry("Time dependent",
                        "false",
                        Bool(),
                        "For 'function': the bed moves, B(x, t), re-sampled at the cell "
                        "centres before every step at the step's end time. The water "
                        "depth is kept, so the volume is unchanged and the free surface "
                        "moves with the bed (as under a sliding mass in the coupled "
                        "scenes). Not in coupled scenes, where the soil moves the bed.");
      prm.declare_entry("Function constants",
                        "",
                        Anything(),
                        "Constants used in the expression, e.g. 'a=0.2, b=0.05'.");
      prm.declare_entry("Table file",
                        "",
                        Anything(),
                        "CSV file x,B for 'table' (relative to the scene file).");
    }



    void
    BedElevation::parse_parameters(dealii::ParameterHandler &prm,
                                   const std::string        &bed_path,
                                   const SceneParameters    &scene)
    {
      path              = bed_path;
      is_time_dependent = prm.get_bool("Time dependent");
      if (prm.get("Type") == "table")
        {
          if (is_time_dependent)
            throw InputError(path + "/Time dependent",
                             "true",
                             "false with 'Type = table' (a moving bed is a function B(x, t))");
          table = std::make_unique<Table1D>(path + "/Table file",
                                            scene.resolve_path(prm.get("Table file")));
        }
      else
        expression = std::make_unique<ParsedExpression>(path + "/Function expression",
                                                        prm.get("Function expression"),
                                                        prm.get("Function constants"));
    }



    double
    BedElevation::value(const double x, const double t) const
    {
      return table ? table->value(x) : expression->value(x, t);
    }



    std::vector<double>
    BedElevation::sample(const WaterMesh &mesh, const double t) const
    {
      std::vector<double> bed(mesh.n_cells());
      for (unsigned int i = 0; i < mesh.n_cells(); ++i)
        {
          bed[i] = value(mesh.center(i), t);
          if (!std::isfinite(bed[i]))
            throw InputError(path,
                             "B(" + to_string(mesh.center(i)) + ")",
                             "a bed elevation that is finite everywhere");
        }
      return bed;
    }



    void
    InitialCondition::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Variable",
                        "water depth",
                        Selection("water depth|free surface"),
                        "Whether 'Function expression' gives the water depth h or the "
                        "free-surface elevation eta = h + B (then h = max(eta - B, 0)).");
      prm.declare_entry("Function expression",
                        "1",
                        Anything(),
                        "Initial h(x) or eta(x) [m], an expression of x.");
      prm.declare_entry("Velocity expression",
                        "0",
                        Anything(),
                        "Initial velocity u(x) [m/s], an expression of x.");
      prm.declare_entry("Function constants",
                        "",
                        Anything(),
                        "Constants used in both expressions, e.g. 'x0=0.5'.");
    }



    void
    InitialCondition::parse_parameters(dealii::ParameterHandler &prm,
                                       const std::string        &condition_path)
    {
      path                        = condition_path;
      level_text                  = prm.get("Function expression");
      const std::string constants = prm.get("Function constants");
      level
        = std::make_unique<ParsedExpression>(path + "/Function expression", level_text, constants);
      velocity        = std::make_unique<ParsedExpression>(path + "/Velocity expression",
                                                    prm.get("Velocity expression"),
                                                    constants);
      is_free_surface = prm.get("Variable") == "free surface";
    }



    void
    InitialCondition::evaluate(const WaterMesh           &mesh,
                               const std::vector<double> &bed,
                               const double               t,
                               std::vector<double>       &depth,
                               std::vector<double>       &discharge) const
    {
      const unsigned int n = mesh.n_cells();
      depth.resize(n);
      discharge.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double x = mesh.center(i);
          const double v = level->value(x, t);
          const double u = velocity->value(x, t);
          if (!std::isfinite(v) || !std::isfinite(u))
            throw InputError(path + "/Function expression",
                             level_text,
                             "expressions giving finite values everywhere (not at x = "
                               + to_string(x) + ")");
          depth[i] = is_free_surface ? std::max(v - bed[i], 0.) : v;
          if (depth[i] < 0.)
            throw InputError(path + "/Function expression",
                             level_text,
                             "a water depth >= 0 everywhere (it is " + to_string(v)
                               + " at x = " + to_string(x) + ")");
          discharge[i] = depth[i] * u;
        }
    }
  } // namespace water
} // namespace slidewave
