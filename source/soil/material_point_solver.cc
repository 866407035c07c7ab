#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <optional>
#include <slidewave/soil/material_point_solver.h>

namespace slidewave
{
  namespace soil
  {
    namespace
    {
      engine::ParticleEngine<SoilModel>::Settings
      engine_settings(const MaterialPointParameters &prm)
      {
        engine::ParticleEngine<SoilModel>::Settings settings;
        settings.shape_function            = prm.shape_function;
        settings.flip_fraction             = prm.flip_fraction;
        settings.velocity_transfer         = prm.velocity_transfer;
        settings.flip_reference_multiplier = reference_time_step_multiplier;
        settings.musl                      = prm.update_scheme != UpdateScheme::usl;
        settings.full_sort_every_step      = prm.full_sort_every_step;
        settings.with_node_positions       = prm.prescribed_velocity != nullptr;
        settings.prescribed_velocity       = prm.prescribed_velocity.get();
        settings.particle_weight           = prm.adaptivity.particle_weight;
        settings.timer_name                = "mpm step";
        return settings;
      }
    } // namespace



    std::unique_ptr<grid::BackgroundGrid>
    MaterialPointSolver::make_grid(const MaterialPointParameters &prm)
    {
      grid::GridChanges changes;
      changes.adaptive_levels     = prm.adaptivity.enabled ? prm.adaptivity.levels : 0;
      changes.adaptivity_interval = prm.adaptivity.interval;
      changes.buffer_cells        = prm.adaptivity.buffer_cells;
      changes.imbalance_threshold = prm.adaptivity.imbalance_threshold;
      changes.balance_interval    = prm.balance_interval;
      return std::make_unique<grid::BackgroundGrid>(prm.lower_left,
                                                    prm.upper_right,
                                                    prm.cell_size,
                                                    changes);
    }



    MaterialPointSolver::MaterialPointSolver(const MaterialPointParameters &parameters,
                                             grid::BackgroundGrid          &grid)
      : prm(parameters)
      , model(prm)
      , grid(grid)
      , engine(grid, model, prm.boundaries, prm.walls, prm.solids, engine_settings(prm))
    {
      if (prm.step_timeline)
        timeline = std::make_unique<core::StepTimeline>();
      engine.set_timeline(timeline.get());
    }



    void
    MaterialPointSolver::setup(const double start_time)
    {
      create_points(start_time);
      initialize_stress();
    }



    void
    MaterialPointSolver::create_points(const double start_time)
    {
      engine.create_points(start_time,
                           prm.regions,
                           prm.particles_per_direction,
                           [this](std::vector<double>    &properties,
                                  const dealii::Point<2> &position,
                                  const unsigned int      region_index,
                                  const double            hx,
                                  const double            hy) {
                             // No point inside a rigid solid.
                             if (grid::inside_a_solid(prm.solids, position))
                               return false;
                             model.fill_new_point(properties, position, region_index, hx, hy);
                             return true;
                           });
    }



    void
    MaterialPointSolver::initialize_stress()
    {
      if (prm.initial_stress == InitialStress::uniform)
        model.set_uniform_stress(engine.point_cloud());
      else if (prm.initial_stress == InitialStress::geostatic)
        model.set_geostatic_stress(engine.point_cloud());
      else if (prm.initial_stress == InitialStress::gravity_loading)
        load_gravity();
    }



    void
    MaterialPointSolver::save(const std::string &prefix)
    {
      engine.save(prefix);
    }



    void
    MaterialPointSolver::load(const std::string &prefix)
    {
      engine.load(prefix);
    }



    MaterialPointSolver::State
    MaterialPointSolver::state() const
    {
      return engine.state();
    }



    void
    MaterialPointSolver::set_state(const State &state)
    {
      engine.set_state(state);
    }



    double
    MaterialPointSolver::load_imbalance() const
    {
      return grid.load_imbalance();
    }



    void
    MaterialPointSolver::load_gravity()
    {
      const double start = engine.time();
      double       t     = 0.;
      model.set_damping(prm.gravity_loading_damping);
      loading_gravity  = true; // every wall holds
      const double end = prm.gravity_loading_time;
      while (t < end * (1. - 1e-12))
        {
          const double dt = std::min(stable_time_step(), end - t);
          advance(dt);
          t += dt;
        }
      engine.set_time(start);
      model.set_damping(prm.damping);
      loading_gravity = false;
      model.finish_gravity_loading(engine.point_cloud());
    }



    void
    MaterialPointSolver::set_point_forces(
      const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
        &force)
    {
      model.set_point_forces(engine.point_cloud(), force);
    }



    dealii::Tensor<1, 2>
    MaterialPointSolver::total_point_force() const
    {
      return model.total_point_force(engine.point_cloud());
    }



    std::array<double, 3>
    MaterialPointSolver::nodal_totals()
    {
      return engine.nodal_totals();
    }



    double
    MaterialPointSolver::stability_limit() const
    {
      return engine.stability_limit();
    }



    double
    MaterialPointSolver::stable_time_step() const
    {
      // A fixed time step is checked against the limit once, at the start (the scene);
      // the run-time guards watch what happens after.
      return prm.fixed_time_step > 0. ? prm.fixed_time_step :
                                        prm.time_step_multiplier * stability_limit();
    }



    void
    MaterialPointSolver::set_timer(dealii::TimerOutput &timer_output)
    {
      engine.set_timer(prm.detailed_timing ? &timer_output : nullptr);
    }



    void
    MaterialPointSolver::advance(const double dt)
    {
      engine.advance(dt, loading_gravity);
    }



    std::string
    MaterialPointSolver::find_invalid_particle() const
    {
      return model.find_invalid_particle(engine.point_cloud());
    }



    MaterialPointSolver::EnergyBudget
    MaterialPointSolver::energy_budget() const
    {
      return model.energy_budget(engine.point_cloud());
    }



    std::string
    MaterialPointSolver::describe_fastest_particle() const
    {
      return model.describe_fastest_particle(engine.point_cloud());
    }



    MaterialPointSolver::Integrals
    MaterialPointSolver::integrals() const
    {
      return model.integrals(engine.point_cloud());
    }
  } // namespace soil
} // namespace slidewave
