#include <algorithm>
#include <cmath>
#include <deal.II/base/function_parser.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/polygon.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/grid/grid_extent.h>
#include <slidewave/grid/load_balancing_parameters.h>
#include <sstream>

namespace slidewave
{
  namespace fluid
  {
    double
    evaluate_xy(const std::string      &parameter,
                const std::string      &expression,
                const dealii::Point<2> &p)
    {
      dealii::FunctionParser<2> function(1);
      initialize_parser(function,
                        "x,y",
                        expression,
                        false,
                        parameter,
                        "an expression of x and y in muparser syntax");
      return function.value(p);
    }



    namespace
    {
      const std::string section = "Free surface flow";

      /** "x0, y0, x1, y1; x0, y0, x1, y1" into boxes inside the domain. */
      std::vector<WaterBox>
      parse_boxes(const std::string &text)
      {
        const std::string     parameter = section + "/Initial water/Water boxes";
        std::vector<WaterBox> boxes;
        std::istringstream    in(text);
        std::string           item;
        while (std::getline(in, item, ';'))
          {
            if (item.find_first_not_of(" \t") == std::string::npos)
              continue;
            const auto v = parse_number_list(parameter,
                                             item,
                                             "rectangles 'x0, y0, x1, y1' separated by ';' "
                                             "with x0 < x1 and y0 < y1",
                                             4);
            if (!(v[0] < v[2] && v[1] < v[3]))
              throw InputError(parameter,
                               item,
                               "rectangles 'x0, y0, x1, y1' with x0 < x1 and y0 < y1");
            boxes.push_back({dealii::Point<2>(v[0], v[1]), dealii::Point<2>(v[2], v[3])});
          }
        return boxes;
      }
    } // namespace



    void
    FreeSurfaceParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection("Grid");
      grid::GridExtent::declare_parameters(prm, "0.01");
      prm.leave_subsection();

      prm.enter_subsection("Adaptive grid");
      {
        prm.declare_entry("Enable",
                          "false",
                          Bool(),
                          "Refine the grid along the water surface (to 'Cell size') and "
                          "coarsen it elsewhere, by 'Levels' levels.");
        prm.declare_entry("Levels", "2", Integer(1, 8), "Levels of refinement.");
        prm.declare_entry("Buffer cells",
                          "2",
                          Integer(0, 20),
                          "Layers of cells kept fine around the cells the surface crosses.");
        prm.declare_entry("Interval", "10", Integer(1), "Steps between two adaptations.");
        prm.declare_entry("Refinement threshold",
                          "0.01",
                          Double(0.),
                          "A cell is kept fine where |grad phi| h exceeds this (phi the "
                          "phase field, h the cell side).");
      }
      prm.leave_subsection();

      prm.enter_subsection("Load balancing");
      grid::LoadBalancingParameters::declare_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Fluids");
      {
        prm.declare_entry("Water density", "1000", Double(0.), "rho_l [kg/m^3].");
        prm.declare_entry("Air density", "1.2", Double(0.), "rho_g [kg/m^3].");
        prm.declare_entry("Water viscosity", "1e-3", Double(0.), "mu_l [Pa s].");
        prm.declare_entry("Air viscosity", "1.8e-5", Double(0.), "mu_g [Pa s].");
        prm.declare_entry("Gravity", "0, -9.81", Anything(), "g_x, g_y [m/s^2].");
      }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      FlowBoundaries::declare_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Initial water");
      {
        prm.declare_entry("Surface elevation",
                          "",
                          Anything(),
                          "eta(x): water below y = eta(x) at the start (an expression of x; "
                          "empty: none).");
        prm.declare_entry("Water boxes",
                          "",
                          Anything(),
                          "Rectangles of water 'x0, y0, x1, y1; ...' (with the surface "
                          "elevation, the water is their union).");
        prm.declare_entry("Velocity",
                          "0; 0",
                          Anything(),
                          "u_x; u_y [m/s] of the water and the air at the start: expressions "
                          "of x and y (muparser syntax).");
      }
      prm.leave_subsection();

      prm.enter_subsection("Porous structure");
      {
        prm.declare_entry("Porosity",
                          "",
                          Anything(),
                          "n(x, y) of a fixed porous structure in the flow (an expression of "
                          "x and y, values in (0, 1]; 1: open water; empty: no structure, "
                          "and nothing of it is computed). Inside it the water feels the "
                          "Darcy drag n^2 mu / kappa (u) and flows through the pores: "
                          "doc/free-surface-flow.md.");
        prm.declare_entry("Permeability",
                          "1e-8",
                          Anything(),
                          "kappa(x, y) [m^2] of the structure where n < 1 (an expression of x "
                          "and y, positive).");
      }
      prm.leave_subsection();

      prm.enter_subsection("Phase field");
      {
        prm.declare_entry("Model",
                          "conservative Allen-Cahn",
                          Selection("conservative Allen-Cahn|Allen-Cahn"),
                          "'conservative Allen-Cahn': d phi/dt + u.grad phi = div(gamma "
                          "(epsilon grad phi - phi (1 - phi) n)), n = grad phi / |grad phi| "
                          "(Chiu and Lin 2011), which keeps the water volume; 'Allen-Cahn': "
                          "paper 002, Eq. 91, the double-well reaction term, which shrinks "
                          "curved surfaces (doc/free-surface-flow.md measures both).");
        prm.declare_entry("Interface thickness",
                          "1",
                          Double(0.25, 8.),
                          "epsilon of the phase-field profile phi = 1 / (1 + exp(-d / "
                          "epsilon)), in units of 'Cell size'.");
        prm.declare_entry("Mobility factor",
                          "1",
                          Double(0.),
                          "gamma = factor x max(largest speed, sqrt(|g| h)) [m/s], the "
                          "velocity at which the profile is restored.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Finite elements");
      prm.declare_entry("Degree",
                        "1",
                        Integer(1, 2),
                        "Of the velocity and the pressure: 1 (Q1-Q1, the grid's nodes, "
                        "which the material points of a coupled scene share) or 2 (Q2-Q2, "
                        "doc/free-surface-flow.md measures both); the phase field is Q1.");
      prm.leave_subsection();

      prm.enter_subsection("Time stepping");
      {
        prm.declare_entry("Theta",
                          "0.5",
                          Double(0.5, 1.),
                          "theta of the theta-scheme for velocity, advection and viscosity "
                          "(0.5: Crank-Nicolson, as paper 002; 1: backward Euler); the "
                          "pressure and the continuity are implicit.");
        prm.declare_entry("Courant number",
                          "0.5",
                          Double(0.),
                          "dt = Courant number x h / max(largest speed, gamma).");
        prm.declare_entry("Maximum time step", "0.01", Double(0.), "[s].");
      }
      prm.leave_subsection();

      prm.enter_subsection("Stabilization");
      prm.declare_entry("Grad-div",
                        "true",
                        Bool(),
                        "The continuity (LSIC) stabilization tau_cont rho (div w)(div u) of "
                        "paper 002 besides SUPG and PSPG.");
      prm.declare_entry(
        "Subscales",
        "quasi-static",
        Selection("quasi-static|dynamic"),
        "The velocity subscale of SUPG and PSPG. quasi-static: u' = -tau_m R / rho with "
        "Tezduyar's tau_m, which holds the time step (paper 002); its pressure "
        "stabilization fades as the step falls below the flow's own (an odd-even pressure "
        "mode in a porous solid at the grains' steps). dynamic: u' is integrated in time at "
        "the quadrature points, rho du'/dt + rho u' / tau_s = -R with tau_s free of the step "
        "(Codina et al. 2007): the same steady state whatever the step.");
      prm.leave_subsection();

      prm.enter_subsection("Linear solver");
      {
        prm.declare_entry("Preconditioner",
                          "ilu",
                          Selection("ilu|amg"),
                          "Of GMRES for the flow (Trilinos ILU(1) per rank or ML's AMG); "
                          "the phase field always uses ILU.");
        prm.declare_entry("Tolerance",
                          "1e-8",
                          Double(0.),
                          "Residual reduction of GMRES (relative to the right-hand side).");
        prm.declare_entry("Maximum iterations", "1000", Integer(1), "Of GMRES per solve.");
        prm.declare_entry("Preconditioner interval",
                          "10",
                          Integer(1, 1000),
                          "The flow's preconditioner is kept for up to this many steps "
                          "(rebuilt earlier when the step length changes by 20 %, when GMRES "
                          "needs twice the iterations it needed with a fresh one, after grid "
                          "changes and checkpoints); 1: rebuilt every step.");
      }
      prm.leave_subsection();

      prm.enter_subsection("Guards");
      {
        prm.declare_entry("Maximum volume drift",
                          "0.05",
                          Double(0.),
                          "The run stops (exit status 2) when the water's balance is off "
                          "by more than this fraction of the initial volume (of the "
                          "domain's area for a tank that starts empty): the water volume "
                          "(the integral of phi, of n phi in a porous solid) plus what "
                          "left through the open and inflow sides, against the initial "
                          "volume (0: never). With Physics = granular water it is checked "
                          "every 'Material points/Check interval' steps, at every output "
                          "and at the end.");
        prm.declare_entry("Maximum speed",
                          "1000",
                          Double(0.),
                          "The run stops when a speed exceeds this [m/s].");
      }
      prm.leave_subsection();

      prm.enter_subsection("Gauges");
      prm.declare_entry("Positions",
                        "",
                        Anything(),
                        "x of the gauges: the water surface elevation there is written every "
                        "step to free_surface/gauges.csv (the format of the shallow water's "
                        "gauges).");
      prm.declare_entry("Pressure probes",
                        "",
                        Anything(),
                        "Points 'x1, y1; x2, y2; ...' [m] inside the grid: the pressure of the "
                        "flow there (the field evaluated in its cell; the total "
                        "pressure, hydrostatic part included: in the granular water the pore "
                        "pressure) is written every step to free_surface/pressure_probes.csv, "
                        "one column 'p(x=.. y=..)' [Pa] per probe, kept by checkpoints as the "
                        "gauges are.");
      prm.leave_subsection();

      prm.enter_subsection("Output");
      prm.declare_entry("Surface polylines",
                        "true",
                        Bool(),
                        "Write the phi = 0.5 contour at every output time as segments in "
                        "free_surface/surface_NNNNN.csv.");
      prm.leave_subsection();

      prm.enter_subsection("Verification");
      {
        prm.declare_entry(
          "Exact solution",
          "none",
          Selection("none|hydrostatic|poiseuille|martin moyce|standing wave|darcy|taylor green"),
          "'hydrostatic': water at rest under its surface eta: the pressure "
          "at every node deeper than 3 epsilon against rho_l |g| (eta - y), "
          "relative to rho_l |g| max depth, and the largest speed (the "
          "spurious currents). 'poiseuille': a channel full of water between "
          "no-slip bottom and top, open ends, gravity along x: u_x at every "
          "node against g_x y (H - y) / (2 nu), relative to its largest "
          "value, at the end. 'martin moyce': the collapse of one water box "
          "of width a and height 2 a against the back (left) wall: the "
          "surge front x / a against the measurements of Martin and Moyce "
          "(1952) at their times T = t sqrt(2 g / a); the tolerance applies "
          "to the largest difference in x / a (no time shift). 'standing "
          "wave': a tank with free-slip sides started from 'Surface "
          "elevation' = d + A cos(pi (x - x0) / L): the period of the surface "
          "at the left wall and its decay against the exact linear theory of "
          "a viscous wave (Lamb's dispersion relation at depth d, free-slip "
          "bottom; omega^2 = g k tanh(k d) without viscosity), k = pi / L (d "
          "the mean of the surface elevation); the tolerance applies to the "
          "relative period error and, where the theory decays the wave by "
          "more than 5 % over the record, to the relative error of the decay "
          "rate. 'darcy': a channel full of "
          "water and of a porous structure (n, kappa uniform), free-slip "
          "bottom and top, open ends, gravity along x: u_x at every node "
          "against rho_l g_x kappa / (n mu_l), relative, at the end. 'taylor "
          "green': a square [x0, x0 + L]^2 of water with free-slip sides "
          "started from 'Initial water/Velocity' = U (sin(k x) cos(k y), "
          "-cos(k x) sin(k y)), k = pi / L: the L2 error of the velocity "
          "against that field times exp(-2 nu k^2 t), relative to its L2 "
          "norm, at the end.");
        prm.declare_entry("Tolerance",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when the error exceeds it.");
      }
      prm.leave_subsection();
    }



    void
    FreeSurfaceParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Grid");
      {
        grid::GridExtent extent;
        extent.parse_parameters(prm, section + "/Grid");
        lower_left  = extent.lower_left;
        upper_right = extent.upper_right;
        cell_size   = extent.cell_size;
      }
      prm.leave_subsection();

      prm.enter_subsection("Adaptive grid");
      {
        adaptive             = prm.get_bool("Enable");
        adaptive_levels      = prm.get_integer("Levels");
        buffer_cells         = prm.get_integer("Buffer cells");
        adaptivity_interval  = prm.get_integer("Interval");
        refinement_threshold = prm.get_double("Refinement threshold");
        if (adaptive)
          {
            const double base = cell_size * (1u << adaptive_levels);
            for (unsigned int d = 0; d < 2; ++d)
              {
                const double n = (upper_right[d] - lower_left[d]) / base;
                if (std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
                  throw InputError(section + "/Adaptive grid/Levels",
                                   std::to_string(adaptive_levels),
                                   "a number of levels such that the coarsest cells (Cell "
                                   "size x 2^Levels = "
                                     + to_string(base) + " m) divide the domain sides");
              }
          }
      }
      prm.leave_subsection();

      prm.enter_subsection("Load balancing");
      {
        grid::LoadBalancingParameters balancing;
        balancing.parse_parameters(prm);
        imbalance_threshold = balancing.imbalance_threshold;
        balance_interval    = balancing.interval;
      }
      prm.leave_subsection();

      prm.enter_subsection("Fluids");
      {
        fluid.water_density   = prm.get_double("Water density");
        fluid.air_density     = prm.get_double("Air density");
        fluid.water_viscosity = prm.get_double("Water viscosity");
        fluid.air_viscosity   = prm.get_double("Air viscosity");
        require_positive(section + "/Fluids/Water density", fluid.water_density);
        require_positive(section + "/Fluids/Air density", fluid.air_density);
        require_positive(section + "/Fluids/Water viscosity", fluid.water_viscosity);
        require_positive(section + "/Fluids/Air viscosity", fluid.air_viscosity);
        const auto g  = parse_number_list(section + "/Fluids/Gravity",
                                         prm.get("Gravity"),
                                         "two numbers g_x, g_y [m/s^2]",
                                         2);
        fluid.gravity = dealii::Tensor<1, 2>({g[0], g[1]});
      }
      prm.leave_subsection();

      prm.enter_subsection("Boundary conditions");
      boundaries.parse_parameters(prm, section);
      prm.leave_subsection();

      prm.enter_subsection("Initial water");
      {
        surface_elevation = prm.get("Surface elevation");
        if (!surface_elevation.empty())
          ParsedExpression(section + "/Initial water/Surface elevation", surface_elevation);
        water_boxes      = parse_boxes(prm.get("Water boxes"));
        initial_velocity = prm.get("Velocity");
        dealii::FunctionParser<2> function(2);
        initialize_parser(function,
                          "x,y",
                          initial_velocity,
                          false,
                          section + "/Initial water/Velocity",
                          "two expressions 'u_x; u_y' of x and y in muparser syntax");
      }
      prm.leave_subsection();

      prm.enter_subsection("Porous structure");
      {
        porosity     = prm.get("Porosity");
        permeability = prm.get("Permeability");
        if (porosity.find_first_not_of(" \t") == std::string::npos)
          porosity.clear();
        else
          {
            const dealii::Point<2> centre = 0.5 * (lower_left + upper_right);
            const double n = evaluate_xy(section + "/Porous structure/Porosity", porosity, centre);
            const double k
              = evaluate_xy(section + "/Porous structure/Permeability", permeability, centre);
            if (!(n > 0. && n <= 1.))
              throw InputError(section + "/Porous structure/Porosity",
                               porosity,
                               "values in (0, 1] (it is " + to_string(n) + " at the centre)");
            if (!(k > 0.))
              throw InputError(section + "/Porous structure/Permeability",
                               permeability,
                               "positive values [m^2] (it is " + to_string(k) + " at the centre)");
          }
      }
      prm.leave_subsection();

      prm.enter_subsection("Phase field");
      {
        phase_field_model  = prm.get("Model") == "Allen-Cahn" ?
                               PhaseFieldModel::allen_cahn :
                               PhaseFieldModel::conservative_allen_cahn;
        thickness_in_cells = prm.get_double("Interface thickness");
        mobility_factor    = prm.get_double("Mobility factor");
      }
      prm.leave_subsection();

      prm.enter_subsection("Finite elements");
      element_degree = prm.get_integer("Degree");
      prm.leave_subsection();

      prm.enter_subsection("Time stepping");
      {
        theta             = prm.get_double("Theta");
        courant_number    = prm.get_double("Courant number");
        maximum_time_step = prm.get_double("Maximum time step");
        require_positive(section + "/Time stepping/Courant number", courant_number);
        require_positive(section + "/Time stepping/Maximum time step", maximum_time_step);
      }
      prm.leave_subsection();

      prm.enter_subsection("Stabilization");
      grad_div          = prm.get_bool("Grad-div");
      dynamic_subscales = prm.get("Subscales") == "dynamic";
      prm.leave_subsection();

      prm.enter_subsection("Linear solver");
      {
        preconditioner          = prm.get("Preconditioner");
        linear_tolerance        = prm.get_double("Tolerance");
        max_iterations          = prm.get_integer("Maximum iterations");
        preconditioner_interval = prm.get_integer("Preconditioner interval");
        require_in_range(
          section + "/Linear solver/Tolerance", linear_tolerance, 0., false, 0.1, true);
      }
      prm.leave_subsection();

      prm.enter_subsection("Guards");
      max_volume_drift = prm.get_double("Maximum volume drift");
      max_speed        = prm.get_double("Maximum speed");
      prm.leave_subsection();

      prm.enter_subsection("Gauges");
      {
        const std::string text = prm.get("Positions");
        gauges                 = text.find_first_not_of(" \t") == std::string::npos ?
                                   std::vector<double>() :
                                   parse_number_list(section + "/Gauges/Positions", text, "numbers x [m]");
        for (const double x : gauges)
          if (x < lower_left[0] || x > upper_right[0])
            throw InputError(section + "/Gauges/Positions",
                             to_string(x),
                             "positions inside the grid, [" + to_string(lower_left[0]) + ", "
                               + to_string(upper_right[0]) + "]");
        const std::string probes = prm.get("Pressure probes");
        const std::string name   = section + "/Gauges/Pressure probes";
        pressure_probes          = probes.find_first_not_of(" \t") == std::string::npos ?
                                     std::vector<dealii::Point<2>>() :
                                     core::parse_polygon(name, probes, "m", "points");
        for (const auto &p : pressure_probes)
          if (p[0] < lower_left[0] || p[0] > upper_right[0] || p[1] < lower_left[1]
              || p[1] > upper_right[1])
            throw InputError(name,
                             probes,
                             "points inside the grid, [" + to_string(lower_left[0]) + ", "
                               + to_string(upper_right[0]) + "] x [" + to_string(lower_left[1])
                               + ", " + to_string(upper_right[1]) + "]");
      }
      prm.leave_subsection();

      prm.enter_subsection("Output");
      write_surface = prm.get_bool("Surface polylines");
      prm.leave_subsection();

      prm.enter_subsection("Verification");
      {
        const std::string type = prm.get("Exact solution");
        exact_solution         = type == "hydrostatic"   ? FlowExactSolution::hydrostatic :
                                 type == "poiseuille"    ? FlowExactSolution::poiseuille :
                                 type == "martin moyce"  ? FlowExactSolution::martin_moyce :
                                 type == "standing wave" ? FlowExactSolution::standing_wave :
                                 type == "darcy"         ? FlowExactSolution::darcy :
                                 type == "taylor green"  ? FlowExactSolution::taylor_green :
                                                           FlowExactSolution::none;
        tolerance              = prm.get_double("Tolerance");
        if (exact_solution == FlowExactSolution::poiseuille
            && (boundaries[2] != FlowBoundary::no_slip || boundaries[3] != FlowBoundary::no_slip))
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'poiseuille' with 'no slip' at Bottom and Top");
        if (exact_solution == FlowExactSolution::martin_moyce)
          {
            const bool one_box = surface_elevation.empty() && water_boxes.size() == 1;
            const auto width   = one_box ? water_boxes[0].upper[0] - water_boxes[0].lower[0] : 0.;
            const auto height  = one_box ? water_boxes[0].upper[1] - water_boxes[0].lower[1] : 0.;
            if (!one_box || std::abs(water_boxes[0].lower[0] - lower_left[0]) > 1e-9 * width
                || std::abs(water_boxes[0].lower[1] - lower_left[1]) > 1e-9 * width
                || std::abs(height - 2. * width) > 1e-6 * width)
              throw InputError(section + "/Verification/Exact solution",
                               type,
                               "'martin moyce' with one water box (and no surface elevation) "
                               "in the lower left corner, its height twice its width (the "
                               "experiment's column)");
          }
        if (exact_solution == FlowExactSolution::standing_wave
            && (surface_elevation.empty() || boundaries[0] != FlowBoundary::free_slip
                || boundaries[1] != FlowBoundary::free_slip))
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'standing wave' with a 'Surface elevation' and 'free slip' at Left "
                           "and Right");
        if (exact_solution == FlowExactSolution::taylor_green
            && (!boundaries.closed() || boundaries[0] != FlowBoundary::free_slip
                || boundaries[1] != FlowBoundary::free_slip
                || boundaries[2] != FlowBoundary::free_slip
                || boundaries[3] != FlowBoundary::free_slip
                || std::abs((upper_right[0] - lower_left[0]) - (upper_right[1] - lower_left[1]))
                     > 1e-9 * (upper_right[0] - lower_left[0])))
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'taylor green' in a square grid with 'free slip' on all four sides");
        if (exact_solution == FlowExactSolution::darcy && porosity.empty())
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'darcy' with a 'Porous structure/Porosity'");
        if (exact_solution == FlowExactSolution::hydrostatic && surface_elevation.empty())
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'hydrostatic' with an 'Initial water/Surface elevation'");
      }
      prm.leave_subsection();

      if (surface_elevation.empty() && water_boxes.empty() && !boundaries.any(FlowBoundary::inflow))
        throw InputError(section + "/Initial water/Water boxes",
                         "",
                         "some water: a 'Surface elevation', at least one box, or an "
                         "'inflow' side");
    }



    grid::GridChanges
    FreeSurfaceParameters::grid_changes() const
    {
      grid::GridChanges changes;
      changes.adaptive_levels     = adaptive ? adaptive_levels : 0;
      changes.adaptivity_interval = adaptivity_interval;
      changes.buffer_cells        = buffer_cells;
      changes.imbalance_threshold = imbalance_threshold;
      changes.balance_interval    = balance_interval;
      return changes;
    }
  } // namespace fluid
} // namespace slidewave
