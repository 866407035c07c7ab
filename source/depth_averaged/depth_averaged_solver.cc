#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <limits>
#include <optional>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/grid/rigid_solid.h>
#include <slidewave/grid/rigid_wall.h>
#include <slidewave/terrain/crs.h>
#include <slidewave/terrain/earth_bounds.h>
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
        // Every rank samples the whole domain: a refusal is made by all of them.
        return terrain::ElevationGrid::from_function(
          [&z, &prm](const double x, const double y) {
            const double value = z.value(dealii::Point<2>(x, y));
            terrain::check_elevation(
              "Depth averaged/Terrain/Elevation", prm.elevation, x, y, value);
            return value;
          },
          prm.lower_left,
          prm.upper_right,
          n(0),
          n(1));
      }

      engine::ParticleEngine<DepthAveragedModel>::Settings
      engine_settings(const DepthAveragedParameters &prm)
      {
        engine::ParticleEngine<DepthAveragedModel>::Settings settings;
        settings.shape_function            = prm.shape_function;
        settings.flip_fraction             = prm.flip_fraction;
        settings.flip_reference_multiplier = reference_courant_number;
        settings.particle_weight           = prm.balancing.particle_weight;
        settings.timer_name                = "depth averaged step";
        return settings;
      }

      /** The CRS of the model's coordinates: the terrain raster's, else 'Terrain/
       *  Coordinates CRS' ("" for none); both given and different is refused. */
      std::string
      model_crs_of(const DepthAveragedParameters &prm)
      {
        const std::string raster_crs
          = prm.terrain_raster == nullptr ? std::string() : prm.terrain_raster->extent().crs_wkt;
        if (prm.coordinates_crs_wkt.empty())
          return raster_crs;
        if (raster_crs.empty())
          return prm.coordinates_crs_wkt;
        if (!terrain::same_crs(raster_crs, prm.coordinates_crs_wkt))
          throw InputError("Depth averaged/Terrain/Coordinates CRS",
                           terrain::crs_name(prm.coordinates_crs_wkt),
                           "empty, or the terrain raster's own CRS, "
                             + terrain::crs_name(raster_crs)
                             + " (the raster defines the model's coordinates)");
        return raster_crs;
      }

      /** No rigid walls in a depth-averaged scene. */
      const std::vector<grid::RigidWall> no_walls;
      /** Nor rigid solids. */
      const std::vector<grid::RigidSolid> no_solids;
    } // namespace



    DepthAveragedSolver::DepthAveragedSolver(const DepthAveragedParameters &parameters,
                                             grid::BackgroundGrid          &grid)
      : prm(with_terrain_raster(parameters))
      , model_crs(model_crs_of(prm))
      , elevation(sample_terrain(prm))
      , release(prm, elevation, model_crs)
      , flow(prm, elevation)
      , grid(grid)
      , engine(grid, flow, prm.sides, no_walls, no_solids, engine_settings(prm))
    {
      // The raster (a warped copy of a large DEM, maybe) has given its CRS and
      // elevations: it is not kept for the run.
      prm.terrain_raster.reset();
    }



    std::unique_ptr<grid::BackgroundGrid>
    DepthAveragedSolver::make_grid(const DepthAveragedParameters &prm)
    {
      grid::GridChanges changes;
      changes.adaptive_levels     = prm.adaptivity.used_levels();
      changes.adaptivity_interval = prm.adaptivity.interval;
      changes.buffer_cells        = prm.adaptivity.buffer_cells;
      // A fast flow may cross the rings of several levels between two adaptations.
      changes.refine_to_finest    = true;
      changes.imbalance_threshold = prm.balancing.imbalance_threshold;
      changes.balance_interval    = prm.balancing.interval;
      return std::make_unique<grid::BackgroundGrid>(prm.lower_left,
                                                    prm.upper_right,
                                                    prm.cell_size,
                                                    changes);
    }



    void
    DepthAveragedSolver::setup(const double start_time)
    {
      // A depth raster's no-data under the release: refused on every rank at once.
      std::optional<dealii::Point<2>> no_data;
      engine.create_points(start_time,
                           release.regions(),
                           prm.particles_per_direction,
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
    }



    void
    DepthAveragedSolver::save(const std::string &prefix)
    {
      engine.save(prefix);
    }



    void
    DepthAveragedSolver::load(const std::string &prefix)
    {
      engine.load(prefix);
    }



    DepthAveragedSolver::State
    DepthAveragedSolver::state() const
    {
      return engine.state();
    }



    void
    DepthAveragedSolver::set_state(const State &state)
    {
      engine.set_state(state);
    }



    double
    DepthAveragedSolver::load_imbalance() const
    {
      return grid.load_imbalance();
    }



    double
    DepthAveragedSolver::stability_limit() const
    {
      return engine.stability_limit();
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
      engine.set_timer(prm.detailed_timing ? &timer_output : nullptr);
    }



    void
    DepthAveragedSolver::advance(const double dt)
    {
      engine.advance(dt);
    }



    std::array<double, 3>
    DepthAveragedSolver::nodal_totals()
    {
      return engine.nodal_totals();
    }



    DepthAveragedSolver::NodalState
    DepthAveragedSolver::nodal_state(const bool with_velocity) const
    {
      // sum_p V_p N_i(x_p) over the lumped area of node i (a quarter of each cell around
      // it): the depth the columns give the node; sum_p m_p v_p N_i / sum_p m_p N_i: their
      // mass-weighted mean velocity there.
      using Vector       = dealii::LinearAlgebra::distributed::Vector<double>;
      const auto  &nodes = engine.nodal_workspace();
      const Vector area  = grid.lumped_nodal_area();
      Vector       volume, mass;
      volume.reinit(nodes.nodal_mass);
      NodalState state;
      if (with_velocity)
        {
          mass.reinit(nodes.nodal_mass);
          for (auto &v : state.velocity)
            v.reinit(nodes.nodal_mass);
        }
      const auto                                  &dofs = grid.dof_handler();
      std::vector<dealii::types::global_dof_index> indices(4);
      // The cells holding points in the grid's order: the same sums in a resumed run.
      engine.point_cloud().for_each_cell_with_particles(
        [&](const auto &cell, const auto &particles_in_cell) {
          const dealii::DoFHandler<2>::active_cell_iterator dof_cell(&dofs.get_triangulation(),
                                                                     cell->level(),
                                                                     cell->index(),
                                                                     &dofs);
          dof_cell->get_dof_indices(indices);
          for (const auto &particle : particles_in_cell)
            {
              const dealii::Point<2> r = particle.get_reference_location();
              const auto             p = particle.get_properties();
              const double           w[4]
                = {(1. - r[0]) * (1. - r[1]), r[0] * (1. - r[1]), (1. - r[0]) * r[1], r[0] * r[1]};
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
        });
      volume.compress(dealii::VectorOperation::add);
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
      z.reinit(engine.nodal_workspace().nodal_mass);
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
