#include <algorithm>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_q.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/fluid/free_surface_solver.h>
#include <slidewave/fluid/phase_profile.h>

namespace slidewave
{
  namespace fluid
  {
    namespace
    {
      /**
       * The initial phase field: phi = 1 / (1 + exp(-d / epsilon)), the equilibrium
       * profile of both interface equations, d the signed distance to the water (positive
       * inside): below the surface elevation, d = eta(x) - y (vertical); in a box, the
       * distance to its nearest side. A box side on the domain's boundary is not a water
       * surface: the box continues beyond it.
       */
      class InitialPhase : public dealii::Function<2>
      {
      public:
        explicit InitialPhase(const FreeSurfaceParameters &parameters)
          : parameters(parameters)
        {
          if (!parameters.surface_elevation.empty())
            surface = std::make_unique<ParsedExpression>(
              "Free surface flow/Initial water/Surface elevation", parameters.surface_elevation);
          const double far = std::numeric_limits<double>::max();
          for (WaterBox box : parameters.water_boxes)
            {
              const double tiny = 1e-9 * parameters.cell_size;
              for (unsigned int d = 0; d < 2; ++d)
                {
                  if (box.lower[d] <= parameters.lower_left[d] + tiny)
                    box.lower[d] = -far;
                  if (box.upper[d] >= parameters.upper_right[d] - tiny)
                    box.upper[d] = far;
                }
              boxes.push_back(box);
            }
        }

        double
        value(const dealii::Point<2> &p, const unsigned int = 0) const override
        {
          double d = -std::numeric_limits<double>::max();
          if (surface)
            d = surface->value(p[0]) - p[1];
          for (const auto &box : boxes)
            {
              const double dx     = std::max({box.lower[0] - p[0], 0., p[0] - box.upper[0]});
              const double dy     = std::max({box.lower[1] - p[1], 0., p[1] - box.upper[1]});
              const double inside = std::min({p[0] - box.lower[0],
                                              box.upper[0] - p[0],
                                              p[1] - box.lower[1],
                                              box.upper[1] - p[1]});
              d = std::max(d, dx > 0. || dy > 0. ? -std::sqrt(dx * dx + dy * dy) : inside);
            }
          const double epsilon = parameters.interface_thickness();
          return equilibrium_phase(d, epsilon);
        }

      private:
        const FreeSurfaceParameters      &parameters;
        std::unique_ptr<ParsedExpression> surface;
        std::vector<WaterBox>             boxes;
      };

      /**
       * The flow's initial velocity (expressions of x and y) and, when @p hydrostatic, the
       * pressure of the initial fluids at rest: p(x, y) = |g_y| times the integral of
       * rho(phi_0(x, s)) ds from y to the top of the grid (midpoint rule on steps of an
       * eighth of the interface thickness at most); 0 otherwise.
       */
      class InitialFlow : public dealii::Function<2>
      {
      public:
        InitialFlow(const FreeSurfaceParameters &parameters, const bool hydrostatic)
          : dealii::Function<2>(3)
          , parameters(parameters)
          , phase(parameters)
          , hydrostatic(hydrostatic)
        {
          velocity.initialize("x,y", parameters.initial_velocity, {});
        }

        double
        value(const dealii::Point<2> &p, const unsigned int component) const override
        {
          if (component < 2)
            return velocity.value(p, component);
          if (!hydrostatic)
            return 0.;
          const double top    = parameters.upper_right[1];
          const double length = top - p[1];
          if (length <= 0.)
            return 0.;
          const double step
            = std::min(parameters.cell_size / 8., parameters.interface_thickness() / 8.);
          const unsigned int n   = static_cast<unsigned int>(std::ceil(length / step));
          const double       ds  = length / n;
          double             sum = 0.;
          for (unsigned int i = 0; i < n; ++i)
            sum += parameters.fluid.density(
              phase.value(dealii::Point<2>(p[0], p[1] + (i + 0.5) * ds)));
          return std::abs(parameters.fluid.gravity[1]) * sum * ds;
        }

      private:
        const FreeSurfaceParameters &parameters;
        const InitialPhase           phase;
        const bool                   hydrostatic;
        dealii::FunctionParser<2>    velocity{2};
      };
    } // namespace



    std::unique_ptr<grid::BackgroundGrid>
    FreeSurfaceSolver::make_grid(const FreeSurfaceParameters &parameters)
    {
      return std::make_unique<grid::BackgroundGrid>(parameters.lower_left,
                                                    parameters.upper_right,
                                                    parameters.cell_size,
                                                    parameters.grid_changes());
    }



    FreeSurfaceSolver::FreeSurfaceSolver(const FreeSurfaceParameters &parameters,
                                         grid::BackgroundGrid        &grid)
      : parameters(parameters)
      , grid(grid)
      , flow(grid,
             dealii::FESystem<2>(dealii::FE_Q<2>(parameters.element_degree),
                                 2,
                                 dealii::FE_Q<2>(parameters.element_degree),
                                 1),
             2)
      , phase(grid)
      , flow_system(grid, flow, phase, parameters)
      , phase_system(grid, flow, phase, parameters)
    {
      if (parameters.adaptive)
        phase.set_refinement_threshold(parameters.refinement_threshold);
      // The work of a cell: its flow and phase dofs (12 + 4 of Q1) in the two solves.
      set_partition_weight_per_dof(100);
      // A scene without a porous structure allocates and evaluates nothing of it.
      if (!parameters.porosity.empty())
        {
          fluid_fraction       = std::make_unique<grid::FiniteElementField>(grid);
          inverse_permeability = std::make_unique<grid::FiniteElementField>(grid);
          PorousMedium medium;
          medium.fluid_fraction       = fluid_fraction.get();
          medium.inverse_permeability = inverse_permeability.get();
          flow_system.set_porous_medium(medium);
          phase_system.set_porous_medium(medium);
        }
    }



    void
    FreeSurfaceSolver::set_initial_state()
    {
      phase.interpolate(InitialPhase(parameters));
      if (solid_flux)
        {
          // No solid until its physics hands its fields over (before every step).
          fluid_fraction->interpolate(dealii::Functions::ConstantFunction<2>(1.));
          inverse_permeability->interpolate(dealii::Functions::ZeroFunction<2>());
          solid_flux->interpolate(dealii::Functions::ZeroFunction<2>(2));
          if (start_flux)
            start_flux->interpolate(dealii::Functions::ZeroFunction<2>(2));
        }
      else if (fluid_fraction)
        {
          // n in (0, 1] and kappa > 0 everywhere: values outside are refused, naming a
          // point where they occur.
          const std::string porosity_name     = "Free surface flow/Porous structure/Porosity";
          const std::string permeability_name = "Free surface flow/Porous structure/Permeability";
          dealii::FunctionParser<2> n(1), kappa(1);
          n.initialize("x,y", parameters.porosity, {});
          kappa.initialize("x,y", parameters.permeability, {});
          std::string problem;
          const auto  check
            = [&](const bool ok, const std::string &what, const dealii::Point<2> &p) {
                if (!ok && problem.empty())
                  problem = what + " at (" + to_string(p[0]) + ", " + to_string(p[1]) + ")";
              };
          fluid_fraction->interpolate(
            dealii::ScalarFunctionFromFunctionObject<2>([&](const dealii::Point<2> &p) {
              const double value = n.value(p);
              check(value > 0. && value <= 1., porosity_name + " = " + to_string(value), p);
              return std::clamp(value, 1e-3, 1.);
            }));
          inverse_permeability->interpolate(
            dealii::ScalarFunctionFromFunctionObject<2>([&](const dealii::Point<2> &p) {
              const double k = kappa.value(p);
              check(k > 0., permeability_name + " = " + to_string(k), p);
              return n.value(p) < 1. && k > 0. ? 1. / k : 0.;
            }));
          const bool bad
            = dealii::Utilities::MPI::max(problem.empty() ? 0 : 1, grid.communicator());
          if (bad)
            throw InputError(problem.empty() ? porosity_name :
                                               problem.substr(0, problem.find(" = ")),
                             problem.empty() ? "(on another rank)" : problem,
                             "porosity in (0, 1] and permeability > 0 everywhere in the grid");
        }
      // The velocity at the start (zero unless 'Initial water/Velocity' says otherwise),
      // the pressure 0 or hydrostatic: both states, so that the first extrapolation is the
      // initial field.
      const InitialFlow velocity(parameters, hydrostatic_start);
      for (unsigned int s = 0; s < flow.n_states(); ++s)
        {
          flow.interpolate(velocity, s);
          flow_system.impose_boundary_values(s, time);
        }
    }



    double
    FreeSurfaceSolver::initial_density(const dealii::Point<2> &point) const
    {
      // (the initial phase field's function, made once: a run asks at every point)
      if (!initial_phase)
        initial_phase = std::make_unique<InitialPhase>(parameters);
      return parameters.fluid.density(initial_phase->value(point));
    }



    void
    FreeSurfaceSolver::set_partition_weight_per_dof(const unsigned int weight)
    {
      flow.set_weight_per_dof(weight);
      phase.set_weight_per_dof(weight);
    }



    void
    FreeSurfaceSolver::enable_moving_solid(const double       grain_density,
                                           const NodalGrains *nodal_grains)
    {
      fluid_fraction       = std::make_unique<grid::FiniteElementField>(grid);
      inverse_permeability = std::make_unique<grid::FiniteElementField>(grid);
      solid_flux
        = std::make_unique<grid::FiniteElementField>(grid,
                                                     dealii::FESystem<2>(dealii::FE_Q<2>(1), 2),
                                                     1);
      PorousMedium medium;
      medium.fluid_fraction       = fluid_fraction.get();
      medium.inverse_permeability = inverse_permeability.get();
      medium.solid_flux           = solid_flux.get();
      medium.grain_density        = grain_density;
      medium.nodal_grains         = grain_density > 0. ? nodal_grains : nullptr;
      flow_system.set_porous_medium(medium);
      medium.nodal_grains = nullptr;
      // With the solid's momentum eliminated its flux field holds the predicted v*; the
      // phase field's mixture divergence needs the flux the last flow solved with, that of
      // the step's start (PhaseFieldSystem).
      if (grain_density > 0.)
        {
          start_flux
            = std::make_unique<grid::FiniteElementField>(grid,
                                                         dealii::FESystem<2>(dealii::FE_Q<2>(1), 2),
                                                         1);
          medium.solid_flux = start_flux.get();
        }
      phase_system.set_porous_medium(medium);
    }



    void
    FreeSurfaceSolver::initialize(const double start_time)
    {
      time = start_time;
      set_initial_state();
      last_dt       = 0.;
      n_steps       = 0;
      water_outflow = 0.;
    }



    void
    FreeSurfaceSolver::setup(const double start_time)
    {
      grid.create();
      time = start_time;
      set_initial_state();
      // The adaptive levels follow the initial surface: refine where the exact initial
      // phi is steep, then set it again on the finer cells (no interpolation error).
      for (unsigned int l = 0; l < grid.adaptive_levels(); ++l)
        {
          if (!grid.adapt())
            break;
          set_initial_state();
        }
      time          = start_time;
      last_dt       = 0.;
      n_steps       = 0;
      water_outflow = 0.;
    }



    void
    FreeSurfaceSolver::save(const std::string &prefix)
    {
      grid.save(prefix);
    }



    void
    FreeSurfaceSolver::load(const std::string &prefix)
    {
      grid.load(prefix);
    }



    double
    FreeSurfaceSolver::profile_velocity() const
    {
      return profile_velocity(max_speed());
    }



    double
    FreeSurfaceSolver::profile_velocity(const double fastest) const
    {
      const double h = grid.cell_size();
      return parameters.mobility_factor
             * std::max(fastest, std::sqrt(parameters.fluid.gravity.norm() * h));
    }



    double
    FreeSurfaceSolver::stable_time_step() const
    {
      return stable_time_step(max_speed()); // one pass over the cells
    }



    double
    FreeSurfaceSolver::stable_time_step(const double fastest) const
    {
      // The advection velocity and the sharpening are explicit: a Courant number on
      // the finest cells with the faster of the two speeds.
      const double speed = std::max(fastest, profile_velocity(fastest));
      // (the cell's size whatever the flow's element degree: the explicit parts are the
      // phase field's, which is Q1)
      const double dt = parameters.courant_number * grid.cell_size() / speed;
      return std::min(dt, parameters.maximum_time_step);
    }



    FluidStepReport
    FreeSurfaceSolver::advance(const double dt)
    {
      // A moving solid's physics drives the grid's changes (between its steps).
      if (!solid_flux)
        grid.change_if_due(n_steps);
      FluidStepReport report;
      // One pass over the cells for the fastest speed, which the sharpening's velocity and
      // the flow's own step (when a coupled physics sets shorter ones: the time scale of
      // dynamic subscales, VelocitySubscales) both take.
      const double      fastest = max_speed();
      const StepLengths lengths{
        dt, last_dt, parameters.dynamic_subscales ? std::max(dt, stable_time_step(fastest)) : dt};
      report.gamma = profile_velocity(fastest);
      report.phase = phase_system.step(lengths, report.gamma);
      report.flow  = flow_system.step(phase_system.previous(), lengths, time + dt);
      water_outflow += phase_system.last_outflow();
      time += dt;
      last_dt = dt;
      ++n_steps;
      return report;
    }



    bool
    FreeSurfaceSolver::state_is_finite() const
    {
      const bool finite = std::isfinite(flow.locally_owned_values(0).l2_norm())
                          && std::isfinite(phase.locally_owned_values(0).l2_norm());
      return finite;
    }
  } // namespace fluid
} // namespace slidewave
