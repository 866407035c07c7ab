#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <limits>
#include <optional>
#include <slidewave/mpm/material_point_solver.h>

namespace slidewave
{
  namespace mpm
  {
    namespace
    {
      TransferKernels<SoilModel>::Settings
      kernel_settings(const MaterialPointParameters &prm, const SoilModel &model)
      {
        TransferKernels<SoilModel>::Settings settings;
        settings.shape_function      = prm.shape_function;
        settings.flip_fraction       = prm.flip_fraction;
        settings.empty_node_mass     = model.empty_node_mass();
        settings.prescribed_velocity = prm.prescribed_velocity.get();
        return settings;
      }
    } // namespace



    MaterialPointSolver::MaterialPointSolver(const MaterialPointParameters &parameters)
      : prm(parameters)
      , model(prm)
      , grid(prm.lower_left,
             prm.upper_right,
             prm.cell_size,
             prm.adaptivity.enabled ? prm.adaptivity.levels : 0)
      , cloud(grid, model.layout(), SoilModel::mass, prm.boundaries)
      , nodes(grid, prm.prescribed_velocity != nullptr)
      , constraints(grid, nodes, prm.boundaries, prm.walls)
      , patches(grid, nodes)
      , kernels(model, cloud, nodes, patches, constraints, kernel_settings(prm, model))
      , damping(parameters.damping)
    {
      // The order of the followers is the order of their rebuilding after a grid change:
      // the points first, then the nodes, and what is built on the nodes.
      grid.attach(cloud);
      grid.attach(nodes);
      grid.attach(constraints);
      grid.attach(patches);
      if (prm.step_timeline)
        timeline = std::make_unique<StepTimeline>();
      kernels.set_timeline(timeline.get());
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
      time = start_time;
      // Until the points exist, every partition of the grid (the refinements below, the
      // repartition) weighs the cells by the points they will get, so that each rank
      // creates the points it keeps: none move and their memory is in cell order.
      weights_from_regions = true;
      grid.create_coarse_grid(
        [this](const dealii::Triangulation<2>::cell_iterator &cell,
               const dealii::Triangulation<2>::CellStatus     status) -> unsigned int {
          return cell_weight(cell, status);
        });
      grid.refine_to_base();
      if (prm.adaptivity.enabled)
        for (unsigned int l = 0; l < prm.adaptivity.levels; ++l)
          grid.refine(cells_near_material(/*from_regions=*/true));
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
          && prm.adaptivity.imbalance_threshold > 0.)
        grid.repartition_initial();
      grid.setup_dofs();
      setup_grid_data();
      cloud.initialize();
      cloud.create(prm.particles_per_direction,
                   prm.regions,
                   [this](std::vector<double>    &properties,
                          const dealii::Point<2> &position,
                          const unsigned int      region_index,
                          const double            hx,
                          const double            hy) {
                     model.fill_new_point(properties, position, region_index, hx, hy);
                     return true;
                   });
      weights_from_regions = false;
      balance_load();
      // The first full sort builds deal.II's search structures of the grid (a few seconds
      // at a million cells): here, not in the first step that needs one. It also puts the
      // memory of points that arrived from other ranks in cell order.
      cloud.sort();
    }



    void
    MaterialPointSolver::initialize_stress()
    {
      if (prm.initial_stress == InitialStress::uniform)
        model.set_uniform_stress(cloud);
      else if (prm.initial_stress == InitialStress::geostatic)
        model.set_geostatic_stress(cloud);
      else if (prm.initial_stress == InitialStress::gravity_loading)
        load_gravity();
    }



    void
    MaterialPointSolver::save(const std::string &prefix)
    {
      cloud.prepare_for_save();
      grid.save(prefix);
    }



    void
    MaterialPointSolver::load(const std::string &prefix)
    {
      grid.create_coarse_grid(
        [this](const dealii::Triangulation<2>::cell_iterator &cell,
               const dealii::Triangulation<2>::CellStatus     status) -> unsigned int {
          return cell_weight(cell, status);
        });
      cloud.initialize();
      grid.load(prefix);
      cloud.load();
      grid.setup_dofs();
      setup_grid_data();
    }



    MaterialPointSolver::State
    MaterialPointSolver::state() const
    {
      return {time, dealii::Utilities::MPI::sum(cloud.lost_mass, MPI_COMM_WORLD), n_steps};
    }



    void
    MaterialPointSolver::set_state(const State &state)
    {
      time    = state.time;
      n_steps = state.n_steps;
      // The lost mass is a sum over ranks: rank 0 carries what was lost before.
      cloud.lost_mass
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? state.lost_mass : 0.;
    }



    void
    MaterialPointSolver::setup_grid_data()
    {
      nodes.reinit();
      constraints.reinit();
      patches.reinit();
    }



    std::vector<bool>
    MaterialPointSolver::cells_near_material(const bool from_regions) const
    {
      // Cells holding material: from the regions (at set-up: any point of the finest
      // lattice of points in the cell lies in a region) or from the particles; then
      // 'Buffer cells' layers of vertex neighbours around them, across ranks.
      const auto        &tria = grid.triangulation();
      std::vector<bool>  near(tria.n_active_cells(), false);
      const unsigned int n = prm.particles_per_direction;
      for (const auto &cell : tria.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          bool has_material = false;
          if (from_regions)
            {
              const dealii::Point<2> origin = cell->vertex(0);
              const double           h      = cell->vertex(1)[0] - origin[0];
              const unsigned int m = n * static_cast<unsigned int>(std::round(h / prm.cell_size));
              for (unsigned int j = 0; j < m && !has_material; ++j)
                for (unsigned int i = 0; i < m && !has_material; ++i)
                  {
                    const dealii::Point<2> x(origin[0] + (i + 0.5) * h / m,
                                             origin[1] + (j + 0.5) * h / m);
                    for (const auto &region : prm.regions)
                      has_material = has_material || region.contains(x);
                  }
            }
          else
            has_material = cloud.particles().n_particles_in_cell(cell) > 0;
          near[cell->active_cell_index()] = has_material;
        }
      return grid.grow(std::move(near), prm.adaptivity.buffer_cells);
    }



    unsigned int
    MaterialPointSolver::cell_weight(const dealii::Triangulation<2>::cell_iterator &cell,
                                     const dealii::Triangulation<2>::CellStatus     status) const
    {
      // The base weight (deal.II's 'weight' signal, unlike the older 'cell_weight', adds
      // none itself) plus the cell's points: those it holds or, before they exist, those
      // the regions will put there with 'per_direction' of them per direction.
      const auto points = [this](const dealii::Triangulation<2>::cell_iterator &c,
                                 const unsigned int                             per_direction) {
        unsigned int n = 0;
        if (weights_from_regions)
          cloud.for_each_point_to_create(c, per_direction, prm.regions, [&n](const auto &...) {
            ++n;
          });
        else
          n = cloud.particles().n_particles_in_cell(c);
        return n;
      };
      const unsigned int per_direction = prm.particles_per_direction;
      unsigned int       n             = 0;
      switch (status)
        {
          case dealii::Triangulation<2>::CELL_PERSIST:
            n = points(cell, per_direction);
            break;
          case dealii::Triangulation<2>::CELL_REFINE:
            // The children's lattices together are the parent's at twice the density.
            n = points(cell, 2 * per_direction);
            break;
          case dealii::Triangulation<2>::CELL_COARSEN:
            for (const auto &child : cell->child_iterators())
              n += points(child, per_direction);
            break;
          default:
            break;
        }
      // p4est takes the weight as an int: saturate rather than wrap around.
      const std::uint64_t weight
        = cell_base_weight + static_cast<std::uint64_t>(prm.adaptivity.particle_weight) * n;
      return static_cast<unsigned int>(
        std::min<std::uint64_t>(weight, std::numeric_limits<int>::max()));
    }



    double
    MaterialPointSolver::load_imbalance() const
    {
      // Max over mean of the ranks' work: cells x 1000 + points x particle weight.
      const double work = static_cast<double>(cell_base_weight)
                            * grid.triangulation().n_locally_owned_active_cells()
                          + static_cast<double>(prm.adaptivity.particle_weight)
                              * cloud.particles().n_locally_owned_particles();
      return grid::BackgroundGrid::imbalance(work);
    }



    void
    MaterialPointSolver::balance_load()
    {
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1
          || !(prm.adaptivity.imbalance_threshold > 0.)
          || load_imbalance() <= prm.adaptivity.imbalance_threshold)
        return;
      // Points travel with their cells to their new ranks (the grid's followers).
      grid.repartition();
      ++n_grid_changes;
    }



    void
    MaterialPointSolver::adapt_grid()
    {
      const bool changes   = grid.flag_for_adaptation(cells_near_material(/*from_regions=*/false));
      const bool rebalance = !changes && prm.adaptivity.imbalance_threshold > 0.
                             && dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
                             && load_imbalance() > prm.adaptivity.imbalance_threshold;
      if (!changes && !rebalance)
        return;
      // Points travel with their cells through refinement, coarsening and repartitioning.
      if (changes)
        grid.execute_coarsening_and_refinement(); // also repartitions by the cell weights
      else
        grid.repartition();
      ++n_grid_changes;
    }



    void
    MaterialPointSolver::load_gravity()
    {
      const double start = time;
      double       t     = 0.;
      damping            = prm.gravity_loading_damping;
      loading_gravity    = true; // every wall holds
      const double end   = prm.gravity_loading_time;
      while (t < end * (1. - 1e-12))
        {
          const double dt = std::min(stable_time_step(), end - t);
          advance(dt);
          t += dt;
        }
      time            = start;
      damping         = prm.damping;
      loading_gravity = false;
      model.finish_gravity_loading(cloud);
    }



    void
    MaterialPointSolver::set_point_forces(
      const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
        &force)
    {
      model.set_point_forces(cloud, force);
    }



    dealii::Tensor<1, 2>
    MaterialPointSolver::total_point_force() const
    {
      return model.total_point_force(cloud);
    }



    std::array<double, 3>
    MaterialPointSolver::nodal_totals()
    {
      kernels.particles_to_grid();
      std::array<double, 3> totals{{nodes.nodal_mass.l1_norm(), 0., 0.}};
      for (unsigned int d = 0; d < 2; ++d)
        totals[d + 1] = nodes.momentum[d].mean_value() * nodes.momentum[d].size();
      return totals;
    }



    double
    MaterialPointSolver::stability_limit() const
    {
      const double max_speed
        = dealii::Utilities::MPI::max(kernels.max_signal_speed(), MPI_COMM_WORLD);
      return max_speed > 0. ? prm.cell_size / max_speed : std::numeric_limits<double>::infinity();
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
      timer = prm.detailed_timing ? &timer_output : nullptr;
    }



    void
    MaterialPointSolver::advance(const double dt)
    {
      // A timer section per part of the step when 'Detailed timing' is on.
      std::optional<dealii::TimerOutput::Scope> part;
      const auto                                start = [&](const char *name) {
        if (timer != nullptr)
          {
            part.reset();
            part.emplace(*timer, name);
          }
      };
      if (timeline)
        timeline->begin_step(n_steps + 1);
      if (prm.adaptivity.enabled && n_steps > 0 && n_steps % prm.adaptivity.interval == 0)
        {
          start("mpm step: grid changes");
          adapt_grid();
        }
      else if (n_steps > 0 && n_steps % prm.balance_interval == 0)
        {
          start("mpm step: grid changes");
          balance_load();
        }
      lap(StepTimeline::grid_changes);
      ++n_steps;
      constraints.update_walls(time, loading_gravity);
      start("mpm step: particles to grid");
      kernels.particles_to_grid();
      start("mpm step: grid update");
      kernels.update_grid(dt, damping, time);
      // Indexed by the points' local indices (their memory slots), which may have gaps
      // after a relocation.
      std::vector<dealii::Point<2>> &new_positions = kernels.new_positions();
      new_positions.resize(cloud.particles().get_property_pool().n_slots());
      start("mpm step: grid to particles");
      if (prm.update_scheme == UpdateScheme::usl)
        {
          kernels.grid_to_particles(dt, /*with_stresses=*/true);
          lap(StepTimeline::gather);
        }
      else
        {
          kernels.grid_to_particles(dt, /*with_stresses=*/false);
          lap(StepTimeline::gather);
          start("mpm step: MUSL re-map and stresses");
          kernels.remap_velocities_to_grid();
          kernels.update_stresses(dt);
          lap(StepTimeline::musl_remap);
        }
      start("mpm step: sort particles");
      const bool full_sort = prm.full_sort_every_step || n_steps % prm.balance_interval == 0;
      if (full_sort)
        for (auto &particle : cloud.particles())
          particle.set_location(new_positions[particle.get_local_index()]);
      // relocate_within_patches() sets the locations itself, also when it gives up.
      if (full_sort || !cloud.relocate_within_patches(new_positions, patches, timeline.get()))
        {
          lap(StepTimeline::relocation);
          ++n_full_sorts;
          cloud.sort();
          lap(StepTimeline::full_sort);
        }
      lap(StepTimeline::relocation);
      time += dt;
    }



    std::string
    MaterialPointSolver::find_invalid_particle() const
    {
      return model.find_invalid_particle(cloud);
    }



    MaterialPointSolver::EnergyBudget
    MaterialPointSolver::energy_budget() const
    {
      return model.energy_budget(cloud);
    }



    std::string
    MaterialPointSolver::describe_fastest_particle() const
    {
      return model.describe_fastest_particle(cloud);
    }



    MaterialPointSolver::Integrals
    MaterialPointSolver::integrals() const
    {
      return model.integrals(cloud);
    }
  } // namespace mpm
} // namespace slidewave
