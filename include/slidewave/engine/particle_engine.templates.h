#ifndef slidewave_engine_particle_engine_templates_h
#define slidewave_engine_particle_engine_templates_h

#include <cmath>
#include <deal.II/base/mpi.h>
#include <optional>
#include <slidewave/engine/particle_engine.h>
#include <slidewave/engine/transfer_kernels.templates.h>

// The definitions of ParticleEngine, included only by the sources of the particle models
// that instantiate it (explicitly, for their model class, next to their kernels).

namespace slidewave
{
  namespace engine
  {
    template <class Model>
    ParticleEngine<Model>::ParticleEngine(grid::BackgroundGrid                    &grid,
                                          const Model                             &model,
                                          const std::array<grid::GridBoundary, 4> &sides,
                                          const std::vector<grid::RigidWall>      &walls,
                                          const std::vector<grid::RigidSolid>     &solids,
                                          const Settings                          &settings)
      : grid(grid)
      , model(model)
      , settings(settings)
      , cloud(grid, model.layout(), Model::mass, sides, settings.particle_weight)
      , nodes(grid,
              settings.with_node_positions || settings.velocity_transfer == VelocityTransfer::apic,
              Model::n_nodal_fields,
              model.n_used_nodal_fields(),
              model.needs_lumped_area())
      , constraints(grid, nodes, sides, walls, solids)
      , patches(grid, nodes)
      , kernels(model,
                cloud,
                nodes,
                patches,
                constraints,
                {settings.shape_function,
                 model.empty_node_mass(),
                 settings.prescribed_velocity,
                 affine_index(model.layout(), settings.velocity_transfer)})
    {
      // The order of the followers is the order of their rebuilding after a grid change:
      // the points first, then the nodes, and what is built on the nodes.
      grid.attach(cloud);
      grid.attach(nodes);
      grid.attach(constraints);
      grid.attach(patches);
    }



    template <class Model>
    void
    ParticleEngine<Model>::create_points(const double                                  start_time,
                                         const std::vector<particles::MaterialRegion> &regions,
                                         const unsigned int                            n,
                                         const particles::PointCloud::PropertyFill    &fill)
    {
      current_time = start_time;
      // Until the points exist, every partition of the grid (the refinements, the
      // repartition) weighs the cells by the points they will get, so that each rank
      // creates the points it keeps: none move and their memory is in cell order.
      cloud.expect_points(regions, n);
      grid.create();
      cloud.initialize();
      cloud.create(n, regions, fill);
      grid.balance();
      // The first full sort builds deal.II's search structures of the grid (a few seconds
      // at a million cells): here, not in the first step that needs one. It also puts the
      // memory of points that arrived from other ranks in cell order.
      cloud.sort();
    }



    template <class Model>
    void
    ParticleEngine<Model>::save(const std::string &prefix) const
    {
      grid.save(prefix);
    }



    template <class Model>
    void
    ParticleEngine<Model>::load(const std::string &prefix)
    {
      // The point cloud initializes its particle handler on the coarse grid
      // (before_checkpoint_load), before the cells are read.
      grid.load(prefix);
    }



    template <class Model>
    typename ParticleEngine<Model>::State
    ParticleEngine<Model>::state() const
    {
      return {current_time, dealii::Utilities::MPI::sum(cloud.lost_mass, MPI_COMM_WORLD), n_steps};
    }



    template <class Model>
    void
    ParticleEngine<Model>::set_state(const State &state)
    {
      current_time = state.time;
      n_steps      = state.n_steps;
      // The lost mass is a sum over ranks: rank 0 carries what was lost before.
      cloud.lost_mass
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? state.lost_mass : 0.;
    }



    template <class Model>
    void
    ParticleEngine<Model>::advance(const double dt, const bool hold_walls)
    {
      begin_step(hold_walls);
      finish_step(dt);
    }



    template <class Model>
    void
    ParticleEngine<Model>::start_part(const char *name)
    {
      if (timer != nullptr)
        {
          part.reset();
          part.emplace(*timer, settings.timer_name + ": " + name);
        }
    }



    template <class Model>
    void
    ParticleEngine<Model>::begin_step(const bool hold_walls)
    {
      // A timer section per part of the step when a timer is given.
      if (timeline)
        timeline->begin_step(n_steps + 1);
      // The reference step of the step's start, before anything moves: the limit the
      // scene's step came from, so that a step at the reference multiplier blends FLIP
      // exactly.
      reference_step
        = blends_by_rate() ? settings.flip_reference_multiplier * stability_limit() : 0.;
      start_part("grid changes");
      grid.change_if_due(n_steps);
      lap(core::StepTimeline::grid_changes);
      ++n_steps;
      constraints.update_walls(current_time, hold_walls);
      start_part("particles to grid");
      kernels.particles_to_grid();
      part.reset();
    }



    template <class Model>
    void
    ParticleEngine<Model>::add_nodal_forces(
      const std::array<grid::NodalWorkspace::Vector, 2> &force)
    {
      // Only the nodes of this step's points: the others are not cleared by the next
      // step's scatter.
      const unsigned int n_owned = nodes.nodal_mass.locally_owned_size();
      for (const unsigned int i : nodes.active())
        if (i < n_owned)
          for (unsigned int d = 0; d < 2; ++d)
            nodes.force[d].local_element(i) += force[d].local_element(i);
    }



    template <class Model>
    void
    ParticleEngine<Model>::finish_step(const double dt)
    {
      start_part("grid update");
      kernels.update_grid(dt, current_time);
      // Indexed by the points' local indices (their memory slots), which may have gaps
      // after a relocation.
      kernels.new_positions().resize(cloud.particles().get_property_pool().n_slots());
      start_part("grid to particles");
      kernels.grid_to_particles(dt, /*with_stresses=*/!settings.musl, flip_fraction_of_step(dt));
      lap(core::StepTimeline::gather);
      if (settings.musl)
        {
          start_part("MUSL re-map and stresses");
          kernels.remap_velocities_to_grid();
          kernels.update_stresses(dt);
          lap(core::StepTimeline::musl_remap);
        }
      if (model.finishes_points())
        {
          start_part("finish particles");
          finish_points();
        }
      start_part("sort particles");
      relocate();
      part.reset();
      current_time += dt;
    }



    template <class Model>
    void
    ParticleEngine<Model>::finish_points()
    {
      std::vector<dealii::Point<2>> &positions = kernels.new_positions();
      new_points.clear();
      new_point_values.clear();
      new_point_positions.clear();
      new_point_buffer.resize(cloud.particles().n_properties_per_particle());
      cloud.for_each_cell_with_particles([&](const auto &cell, const auto &particles_in_cell) {
        for (auto &particle : particles_in_cell)
          {
            auto             p = particle.get_properties();
            dealii::Point<2> child_x;
            if (!model.finish_point(
                  p, positions[particle.get_local_index()], new_point_buffer.data(), child_x))
              continue;
            new_points.push_back({cell,
                                  particle.get_location(),
                                  particle.get_reference_location(),
                                  particle.get_id()});
            new_point_values.insert(new_point_values.end(),
                                    new_point_buffer.begin(),
                                    new_point_buffer.end());
            new_point_positions.push_back(child_x);
          }
      });
      const std::vector<unsigned int> slots = cloud.add_points(new_points, new_point_values);
      if (slots.empty())
        return;
      positions.resize(cloud.particles().get_property_pool().n_slots());
      for (unsigned int k = 0; k < slots.size(); ++k)
        positions[slots[k]] = new_point_positions[k];
    }



    template <class Model>
    void
    ParticleEngine<Model>::relocate()
    {
      const std::vector<dealii::Point<2>> &new_positions = kernels.new_positions();
      const bool                           full_sort
        = settings.full_sort_every_step || n_steps % grid.changes().balance_interval == 0;
      if (full_sort)
        for (auto &particle : cloud.particles())
          particle.set_location(new_positions[particle.get_local_index()]);
      // relocate_within_patches() sets the locations itself, also when it gives up.
      if (full_sort || !cloud.relocate_within_patches(new_positions, patches, timeline))
        {
          lap(core::StepTimeline::relocation);
          ++n_full_sorts;
          cloud.sort();
          lap(core::StepTimeline::full_sort);
        }
      lap(core::StepTimeline::relocation);
    }



    template <class Model>
    double
    ParticleEngine<Model>::max_signal_speed() const
    {
      return dealii::Utilities::MPI::max(kernels.max_signal_speed(), MPI_COMM_WORLD);
    }



    template <class Model>
    double
    ParticleEngine<Model>::stability_limit() const
    {
      return model.stability_limit(max_signal_speed(), grid.cell_size());
    }



    template <class Model>
    bool
    ParticleEngine<Model>::blends_by_rate() const
    {
      const double flip = settings.flip_fraction;
      return settings.velocity_transfer == VelocityTransfer::flip
             && settings.flip_reference_multiplier > 0. && flip > 0. && flip < 1.;
    }



    template <class Model>
    double
    ParticleEngine<Model>::flip_fraction_of_step(const double dt) const
    {
      // (reference_step is 0 unless the blend is a rate: begin_step())
      const double flip = settings.flip_fraction;
      if (!(reference_step > 0.) || !std::isfinite(reference_step))
        return flip;
      // At the reference step dt / reference_step is 1 exactly (the scenes' step is the
      // same expression of the same state) and the blend is flip_fraction itself.
      return std::pow(flip, dt / reference_step);
    }



    template <class Model>
    std::array<double, 3>
    ParticleEngine<Model>::nodal_totals()
    {
      scatter_points();
      std::array<double, 3> totals{{nodes.nodal_mass.l1_norm(), 0., 0.}};
      for (unsigned int d = 0; d < 2; ++d)
        totals[d + 1] = nodes.momentum[d].mean_value() * nodes.momentum[d].size();
      return totals;
    }
  } // namespace engine
} // namespace slidewave

#endif
