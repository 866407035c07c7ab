#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <limits>
#include <optional>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/terrain/elevation_table.h>
#include <slidewave/terrain/raster_terrain.h>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      /** @p prm with its terrain raster open: the one the scene opened for its footprint
       *  or, if none, one opened here, so that the CRS and the elevations come from one
       *  opening and one warp of the file. */
      DepthAveragedParameters
      with_terrain_raster(DepthAveragedParameters prm)
      {
        if (!prm.elevation_raster.empty() && prm.terrain_raster == nullptr)
          prm.terrain_raster
            = std::make_shared<const terrain::RasterSource>("Depth averaged/Terrain/Raster file",
                                                            prm.elevation_raster,
                                                            prm.raster_options);
        return prm;
      }

      /** The terrain under the domain: the raster's window, the table, or the expression
       *  sampled on a grid of the given spacing. */
      terrain::ElevationGrid
      sample_terrain(const DepthAveragedParameters &prm)
      {
        if (prm.terrain_raster != nullptr)
          return prm.terrain_raster->window(prm.lower_left, prm.upper_right);
        if (!prm.elevation_table.empty())
          {
            auto table = terrain::read_elevation_table("Depth averaged/Terrain/Table file",
                                                       prm.elevation_table);
            for (const auto &corner : {prm.lower_left, prm.upper_right})
              if (!table.contains(corner))
                throw InputError("Depth averaged/Terrain/Table file",
                                 prm.elevation_table,
                                 "a grid of elevations covering the domain ["
                                   + to_string(prm.lower_left[0]) + ", "
                                   + to_string(prm.upper_right[0]) + "] x ["
                                   + to_string(prm.lower_left[1]) + ", "
                                   + to_string(prm.upper_right[1]) + "]");
            return table;
          }
        dealii::FunctionParser<2> z(1);
        z.initialize("x,y", prm.elevation, {{"pi", M_PI}});
        const auto n = [&](const unsigned int d) {
          return static_cast<unsigned int>(
                   std::ceil((prm.upper_right[d] - prm.lower_left[d]) / prm.terrain_spacing - 1e-9))
                 + 1;
        };
        return terrain::ElevationGrid::from_function(
          [&z](const double x, const double y) { return z.value(dealii::Point<2>(x, y)); },
          prm.lower_left,
          prm.upper_right,
          n(0),
          n(1));
      }

      mpm::TransferKernels<DepthAveragedModel>::Settings
      kernel_settings(const DepthAveragedParameters &prm, const DepthAveragedModel &model)
      {
        mpm::TransferKernels<DepthAveragedModel>::Settings settings;
        settings.shape_function  = prm.shape_function;
        settings.flip_fraction   = prm.flip_fraction;
        settings.empty_node_mass = model.empty_node_mass();
        return settings;
      }

      /** Partitioning weight of a cell without points (deal.II's convention). */
      constexpr unsigned int cell_base_weight = 1000;
    } // namespace



    DepthAveragedSolver::DepthAveragedSolver(const DepthAveragedParameters &parameters)
      : prm(with_terrain_raster(parameters))
      , model_crs(prm.terrain_raster == nullptr ? std::string() :
                                                  prm.terrain_raster->extent().crs_wkt)
      , elevation(sample_terrain(prm))
      , release(prm, elevation, model_crs)
      , flow(prm, elevation)
      , grid(prm.lower_left, prm.upper_right, prm.cell_size, 0)
      , cloud(grid, flow.layout(), DepthAveragedModel::mass, prm.sides)
      , nodes(grid,
              /*with_node_positions=*/false,
              /*with_resistance=*/true,
              /*with_depth=*/prm.depth_update == DepthUpdate::projection)
      , constraints(grid, nodes, prm.sides, no_walls)
      , patches(grid, nodes)
      , kernels(flow, cloud, nodes, patches, constraints, kernel_settings(prm, flow))
    {
      // The raster (a warped copy of a large DEM, maybe) has given its CRS and
      // elevations: it is not kept for the run.
      prm.terrain_raster.reset();
      // Rebuilt in this order after a grid change: the points, the nodes, then what is
      // built on the nodes.
      grid.attach(cloud);
      grid.attach(nodes);
      grid.attach(constraints);
      grid.attach(patches);
    }



    void
    DepthAveragedSolver::setup(const double start_time)
    {
      time = start_time;
      // Until the points exist, the cells weigh the points the release will put there, so
      // that each rank creates the points it keeps.
      weights_from_release = true;
      grid.create_coarse_grid([this](const dealii::Triangulation<2>::cell_iterator &cell,
                                     const dealii::Triangulation<2>::CellStatus     status) {
        return cell_weight(cell, status);
      });
      grid.refine_to_base();
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1
          && prm.balancing.imbalance_threshold > 0.)
        grid.repartition_initial();
      grid.setup_dofs();
      nodes.reinit();
      constraints.reinit();
      patches.reinit();
      cloud.initialize();
      // A depth raster's no-data under the release: refused on every rank at once.
      std::optional<dealii::Point<2>> no_data;
      cloud.create(prm.particles_per_direction,
                   release.regions(),
                   [this, &no_data](std::vector<double>    &properties,
                                    const dealii::Point<2> &position,
                                    const unsigned int      region,
                                    const double            hx,
                                    const double            hy) {
                     const double h = release.depth(position, region);
                     if (std::isnan(h))
                       {
                         no_data = position;
                         return false;
                       }
                     return flow.fill_new_point(
                       properties, position, h, release.velocity(position), hx, hy);
                   });
      weights_from_release = false;
      const int rank_with_no_data
        = dealii::Utilities::MPI::min(no_data ? static_cast<int>(
                                        dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)) :
                                                std::numeric_limits<int>::max(),
                                      MPI_COMM_WORLD);
      if (rank_with_no_data != std::numeric_limits<int>::max())
        {
          std::vector<double> where{no_data ? (*no_data)[0] : 0., no_data ? (*no_data)[1] : 0.};
          MPI_Bcast(where.data(), 2, MPI_DOUBLE, rank_with_no_data, MPI_COMM_WORLD);
          throw InputError("Depth averaged/Release/Depth raster",
                           prm.depth_raster,
                           "a depth at every point of the release area (the pixel holding ("
                             + to_string(where[0]) + ", " + to_string(where[1]) + ") is no-data)");
        }
      balance_load();
      cloud.sort();
    }



    void
    DepthAveragedSolver::save(const std::string &prefix)
    {
      cloud.prepare_for_save();
      grid.save(prefix);
    }



    void
    DepthAveragedSolver::load(const std::string &prefix)
    {
      grid.create_coarse_grid([this](const dealii::Triangulation<2>::cell_iterator &cell,
                                     const dealii::Triangulation<2>::CellStatus     status) {
        return cell_weight(cell, status);
      });
      cloud.initialize();
      grid.load(prefix);
      cloud.load();
      grid.setup_dofs();
      nodes.reinit();
      constraints.reinit();
      patches.reinit();
    }



    DepthAveragedSolver::State
    DepthAveragedSolver::state() const
    {
      return {time, dealii::Utilities::MPI::sum(cloud.lost_mass, MPI_COMM_WORLD), n_steps};
    }



    void
    DepthAveragedSolver::set_state(const State &state)
    {
      time    = state.time;
      n_steps = state.n_steps;
      // A sum over ranks: rank 0 carries what was lost before.
      cloud.lost_mass
        = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? state.lost_mass : 0.;
    }



    unsigned int
    DepthAveragedSolver::cell_weight(const dealii::Triangulation<2>::cell_iterator &cell,
                                     const dealii::Triangulation<2>::CellStatus     status) const
    {
      // The grid is never refined or coarsened: a cell persists or is a coarse cell being
      // refined to the base grid (before any point exists).
      unsigned int n = 0;
      if (status == dealii::Triangulation<2>::CELL_PERSIST)
        {
          if (weights_from_release)
            cloud.for_each_point_to_create(cell,
                                           prm.particles_per_direction,
                                           release.regions(),
                                           [&n](const auto &...) { ++n; });
          else
            n = cloud.particles().n_particles_in_cell(cell);
        }
      const std::uint64_t weight
        = cell_base_weight + static_cast<std::uint64_t>(prm.balancing.particle_weight) * n;
      return static_cast<unsigned int>(
        std::min<std::uint64_t>(weight, std::numeric_limits<int>::max()));
    }



    double
    DepthAveragedSolver::load_imbalance() const
    {
      const double work = static_cast<double>(cell_base_weight)
                            * grid.triangulation().n_locally_owned_active_cells()
                          + static_cast<double>(prm.balancing.particle_weight)
                              * cloud.particles().n_locally_owned_particles();
      return grid::BackgroundGrid::imbalance(work);
    }



    void
    DepthAveragedSolver::balance_load()
    {
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1
          || !(prm.balancing.imbalance_threshold > 0.)
          || load_imbalance() <= prm.balancing.imbalance_threshold)
        return;
      grid.repartition();
    }



    double
    DepthAveragedSolver::stability_limit() const
    {
      // Eq. 22 with the wave speed: h / max_p (|v_p| + sqrt(g h_p)); and the viscous
      // limit of an explicit step, rho h^2 / (4 eta) with eta = 2 mu + tau_Y m the largest
      // viscosity of the (regularized) Bingham law: its stress is eta D, and the largest
      // eigenvalue of div(eta D) on the grid is below 8 eta / (rho h^2).
      const double max_speed
        = dealii::Utilities::MPI::max(kernels.max_signal_speed(), MPI_COMM_WORLD);
      const double h   = prm.cell_size;
      const double eta = 2. * prm.viscosity + prm.yield_stress * prm.regularization;
      const double advective
        = max_speed > 0. ? h / max_speed : std::numeric_limits<double>::infinity();
      const double viscous
        = eta > 0. ? prm.density * h * h / (4. * eta) : std::numeric_limits<double>::infinity();
      return std::min(advective, viscous);
    }



    double
    DepthAveragedSolver::stable_time_step() const
    {
      return prm.fixed_time_step > 0. ? prm.fixed_time_step :
                                        prm.courant_number * stability_limit();
    }



    void
    DepthAveragedSolver::set_timer(dealii::TimerOutput &timer_output)
    {
      timer = prm.detailed_timing ? &timer_output : nullptr;
    }



    void
    DepthAveragedSolver::advance(const double dt)
    {
      std::optional<dealii::TimerOutput::Scope> part;
      const auto                                start = [&](const char *name) {
        if (timer != nullptr)
          {
            part.reset();
            part.emplace(*timer, name);
          }
      };
      if (n_steps > 0 && n_steps % prm.balancing.interval == 0)
        {
          start("depth averaged step: load balancing");
          balance_load();
        }
      ++n_steps;
      start("depth averaged step: particles to grid");
      kernels.particles_to_grid();
      start("depth averaged step: grid update");
      kernels.update_grid(dt, /*damping=*/0., time);
      std::vector<dealii::Point<2>> &new_positions = kernels.new_positions();
      new_positions.resize(cloud.particles().get_property_pool().n_slots());
      start("depth averaged step: grid to particles");
      kernels.grid_to_particles(dt, /*with_stresses=*/true);
      start("depth averaged step: sort particles");
      const bool full_sort = n_steps % prm.balancing.interval == 0;
      if (full_sort)
        for (auto &particle : cloud.particles())
          particle.set_location(new_positions[particle.get_local_index()]);
      if (full_sort || !cloud.relocate_within_patches(new_positions, patches, nullptr))
        cloud.sort();
      time += dt;
    }



    std::array<double, 3>
    DepthAveragedSolver::nodal_totals()
    {
      kernels.particles_to_grid();
      std::array<double, 3> totals{{nodes.nodal_mass.l1_norm(), 0., 0.}};
      for (unsigned int d = 0; d < 2; ++d)
        totals[d + 1] = nodes.momentum[d].mean_value() * nodes.momentum[d].size();
      return totals;
    }



    DepthAveragedSolver::NodalState
    DepthAveragedSolver::nodal_state(const bool with_velocity) const
    {
      // sum_p V_p N_i(x_p) over the lumped area of node i (a quarter of each cell around
      // it): the depth the columns give the node; sum_p m_p v_p N_i / sum_p m_p N_i: their
      // mass-weighted mean velocity there.
      using Vector = dealii::LinearAlgebra::distributed::Vector<double>;
      Vector volume, area, mass;
      volume.reinit(nodes.nodal_mass);
      area.reinit(nodes.nodal_mass);
      NodalState state;
      if (with_velocity)
        {
          mass.reinit(nodes.nodal_mass);
          for (auto &v : state.velocity)
            v.reinit(nodes.nodal_mass);
        }
      const auto                                  &dofs = grid.dof_handler();
      std::vector<dealii::types::global_dof_index> indices(4);
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            const double quarter = 0.25 * cell->measure();
            for (const auto i : indices)
              area[i] += quarter;
            for (const auto &particle : cloud.particles().particles_in_cell(cell))
              {
                const dealii::Point<2> r    = particle.get_reference_location();
                const auto             p    = particle.get_properties();
                const double           w[4] = {(1. - r[0]) * (1. - r[1]),
                                               r[0] * (1. - r[1]),
                                               (1. - r[0]) * r[1],
                                               r[0] * r[1]};
                for (unsigned int k = 0; k < 4; ++k)
                  volume[indices[k]] += w[k] * p[property::volume];
                if (with_velocity)
                  for (unsigned int k = 0; k < 4; ++k)
                    {
                      mass[indices[k]] += w[k] * p[property::mass];
                      state.velocity[0][indices[k]]
                        += w[k] * p[property::mass] * p[property::velocity_x];
                      state.velocity[1][indices[k]]
                        += w[k] * p[property::mass] * p[property::velocity_y];
                    }
              }
          }
      volume.compress(dealii::VectorOperation::add);
      area.compress(dealii::VectorOperation::add);
      if (with_velocity)
        for (Vector *v : {&mass, &state.velocity[0], &state.velocity[1]})
          v->compress(dealii::VectorOperation::add);
      for (unsigned int i = 0; i < volume.locally_owned_size(); ++i)
        {
          volume.local_element(i) /= area.local_element(i);
          if (with_velocity)
            for (auto &v : state.velocity)
              v.local_element(i)
                = mass.local_element(i) > 0. ? v.local_element(i) / mass.local_element(i) : 0.;
        }
      state.depth = std::move(volume);
      state.depth.update_ghost_values();
      if (with_velocity)
        for (auto &v : state.velocity)
          v.update_ghost_values();
      return state;
    }



    dealii::LinearAlgebra::distributed::Vector<double>
    DepthAveragedSolver::nodal_elevation() const
    {
      dealii::LinearAlgebra::distributed::Vector<double> z;
      z.reinit(nodes.nodal_mass);
      const auto &dofs = grid.dof_handler();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto i = cell->vertex_dof_index(v, 0);
              if (z.in_local_range(i))
                z[i] = elevation.value(cell->vertex(v));
            }
      z.update_ghost_values();
      return z;
    }
  } // namespace depth_averaged
} // namespace slidewave
