#include <algorithm>
#include <cmath>
#include <deal.II/base/function.h>
#include <deal.II/fe/fe_q.h>
#include <limits>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/fluid/free_surface_solver.h>

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
          return 1. / (1. + std::exp(std::clamp(-d / epsilon, -700., 700.)));
        }

      private:
        const FreeSurfaceParameters      &parameters;
        std::unique_ptr<ParsedExpression> surface;
        std::vector<WaterBox>             boxes;
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
      , flow(grid, dealii::FESystem<2>(dealii::FE_Q<2>(1), 2, dealii::FE_Q<2>(1), 1), 2)
      , phase(grid)
      , flow_system(grid, flow, phase, parameters)
      , phase_system(grid, flow, phase, parameters)
    {
      if (parameters.adaptive)
        phase.set_refinement_threshold(parameters.refinement_threshold);
      // The work of a cell: its flow and phase dofs (12 + 4 of Q1) in the two solves.
      flow.set_weight_per_dof(100);
      phase.set_weight_per_dof(100);
    }



    void
    FreeSurfaceSolver::set_initial_state()
    {
      phase.interpolate(InitialPhase(parameters));
      for (unsigned int s = 0; s < flow.n_states(); ++s)
        {
          flow.locally_owned_values(s) = 0.;
          flow.values_changed(s);
        }
    }



    void
    FreeSurfaceSolver::setup(const double start_time)
    {
      grid.create();
      set_initial_state();
      // The adaptive levels follow the initial surface: refine where the exact initial
      // phi is steep, then set it again on the finer cells (no interpolation error).
      for (unsigned int l = 0; l < grid.adaptive_levels(); ++l)
        {
          if (!grid.adapt())
            break;
          set_initial_state();
        }
      time    = start_time;
      last_dt = 0.;
      n_steps = 0;
    }



    void
    FreeSurfaceSolver::save(const std::string &prefix) const
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
      const double h = grid.cell_size();
      return parameters.mobility_factor
             * std::max(max_speed(), std::sqrt(parameters.fluid.gravity.norm() * h));
    }



    double
    FreeSurfaceSolver::stable_time_step() const
    {
      // The advection velocity and the sharpening are explicit: a Courant number on
      // the finest cells with the faster of the two speeds.
      const double speed = std::max(max_speed(), profile_velocity());
      const double dt    = parameters.courant_number * grid.cell_size() / speed;
      return std::min(dt, parameters.maximum_time_step);
    }



    FluidStepReport
    FreeSurfaceSolver::advance(const double dt)
    {
      grid.change_if_due(n_steps);
      FluidStepReport   report;
      const StepLengths lengths{dt, last_dt};
      report.gamma = profile_velocity();
      report.phase = phase_system.step(lengths, report.gamma);
      report.flow  = flow_system.step(phase_system.previous(), lengths);
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
