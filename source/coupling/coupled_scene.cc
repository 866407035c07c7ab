#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <filesystem>
#include <iostream>
#include <limits>
#include <slidewave/core/format.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/progress_reporter.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/coupling/coupled_scene.h>

namespace slidewave
{
  namespace coupling
  {
    namespace
    {
      const std::string section = "Coupling";
    } // namespace



    void
    CouplingParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Water density",
                        "1000",
                        Double(0.),
                        "rho_w [kg/m^3]: the water's pressure and bed shear on the soil "
                        "(paper 000, Eq. 10).");
      prm.declare_entry("Water cells",
                        "grid columns",
                        Selection("grid columns|water mesh"),
                        "'grid columns': the water cells are the columns of the material "
                        "points' grid at set-up (non-uniform where it is refined; the bed is "
                        "the soil surface of each column, no interpolation between meshes). "
                        "'water mesh': the cells of 'Shallow water/Mesh'; the bed is "
                        "reconstructed on them by monotone cubic interpolation through the "
                        "column surfaces.");
      prm.declare_entry("Soil surface",
                        "envelope",
                        Selection("envelope|top"),
                        "How the soil makes the water's bed in each grid column. 'top': the "
                        "top of the highest point domain in the column, max (y_p + l_p); it "
                        "jumps by the height of a face when the first point enters a column. "
                        "'envelope': the mean across the column of the upper envelope of the "
                        "point domains (8 samples per column; the grid's floor where there "
                        "is no soil): the top where the soil fills the column, and growing "
                        "continuously as a face moves into a column.");
      prm.declare_entry("Water loads on soil",
                        "true",
                        Bool(),
                        "Whether the water's pressure and bed shear act on the soil (false: "
                        "one-way coupling, the soil moves the water only).");
      prm.declare_entry("Maximum substeps",
                        "1",
                        Integer(1, 1000),
                        "1: one step of both solvers per coupled step, the smaller of the two "
                        "stable steps (Eq. 38). N > 1: the solver with the smaller stable step "
                        "takes up to N steps inside one step of the other; bed and loads are "
                        "exchanged once per coupled step.");
      prm.enter_subsection("Verification");
      {
        prm.declare_entry("Tolerance on volume balance",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when, at any step, the water "
                          "volume differs from the initial volume plus the boundary inflow by "
                          "more than this fraction of the initial volume.");
        prm.declare_entry("Tolerance on free surface",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when, at any step, the free "
                          "surface over the wet cells is not flat to within this [m] (max eta "
                          "- min eta): the coupled lake at rest.");
        prm.declare_entry("Tolerance on soil speed",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when a material point ever "
                          "moves faster than this [m/s]: soil that must stay at rest.");
      }
      prm.leave_subsection();
    }



    void
    CouplingParameters::parse_parameters(dealii::ParameterHandler &prm)
    {
      water_density = prm.get_double("Water density");
      water_cells   = prm.get("Water cells") == "grid columns" ? WaterCells::grid_columns :
                                                                 WaterCells::water_mesh;
      soil_surface  = prm.get("Soil surface") == "top" ? SoilSurface::top : SoilSurface::envelope;
      loads_on_soil = prm.get_bool("Water loads on soil");
      maximum_substeps = prm.get_integer("Maximum substeps");
      if (!(water_density > 0.))
        throw InputError(section + "/Water density",
                         to_string(water_density),
                         "a density > 0 kg/m^3");
      prm.enter_subsection("Verification");
      tolerance_volume       = prm.get_double("Tolerance on volume balance");
      tolerance_free_surface = prm.get_double("Tolerance on free surface");
      tolerance_soil_speed   = prm.get_double("Tolerance on soil speed");
      prm.leave_subsection();
    }



    void
    CoupledScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection(section);
      CouplingParameters::declare_parameters(prm);
      prm.leave_subsection();
    }



    CoupledScene::CoupledScene(const SceneParameters    &scene_parameters,
                               dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , particle_output(scene_parameters.output_directory)
    {
      if (scene.resume || scene.checkpoint_steps > 0 || scene.checkpoint_minutes > 0.
          || scene.checkpoint_at_end)
        throw InputError(scene.resume ? "Checkpoint/Resume" : "Checkpoint",
                         scene.resume ? "true" : "set",
                         "no checkpoint settings in a coupled scene (checkpoints exist for "
                         "material points only, for now)");

      prm.enter_subsection(section);
      coupling.parse_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Material points");
      soil_parameters.parse_parameters(prm, "Material points");
      check_interval = prm.get_integer("Check interval");
      prm.leave_subsection();
      soil_parameters.point_forces = coupling.loads_on_soil;

      const std::string water_section = "Shallow water";
      prm.enter_subsection(water_section);
      {
        water_parameters.parse_parameters(prm, water_section);
        if (coupling.water_cells == WaterCells::water_mesh)
          {
            prm.enter_subsection("Mesh");
            configured_mesh = water::WaterMesh::from_parameters(prm, water_section + "/Mesh");
            prm.leave_subsection();
          }
        const char *ends[2] = {"Left boundary", "Right boundary"};
        for (unsigned int e = 0; e < 2; ++e)
          {
            prm.enter_subsection(ends[e]);
            boundaries[e].parse_parameters(prm, water_section + "/" + ends[e], scene);
            prm.leave_subsection();
          }
        prm.enter_subsection("Bed");
        terrain.parse_parameters(prm, water_section + "/Bed", scene);
        if (terrain.time_dependent())
          throw InputError(water_section + "/Bed/Time dependent",
                           "true",
                           "false in a coupled scene (the soil moves the bed; 'Bed' is the "
                           "fixed terrain)");
        prm.leave_subsection();
        prm.enter_subsection("Initial condition");
        initial_condition.parse_parameters(prm, water_section + "/Initial condition");
        prm.leave_subsection();
        prm.enter_subsection("Gauges");
        gauge_text = prm.get("Positions");
        prm.leave_subsection();
      }
      prm.leave_subsection();

      const double left = soil_parameters.lower_left[0], right = soil_parameters.upper_right[0];
      if (configured_mesh
          && (configured_mesh->left_end() < left - 1e-12 * (right - left)
              || configured_mesh->right_end() > right + 1e-12 * (right - left)))
        throw InputError(water_section + "/Mesh",
                         "[" + to_string(configured_mesh->left_end()) + ", "
                           + to_string(configured_mesh->right_end()) + "]",
                         "a water mesh inside the material points' grid [" + to_string(left) + ", "
                           + to_string(right) + "] (x)");
      gauges.parse_positions(water_section + "/Gauges/Positions",
                             gauge_text,
                             configured_mesh ? configured_mesh->left_end() : left,
                             configured_mesh ? configured_mesh->right_end() : right);
    }



    void
    CoupledScene::setup_water()
    {
      const double cell_size = soil_parameters.cell_size;
      const double left = soil_parameters.lower_left[0], right = soil_parameters.upper_right[0];

      // The grid columns: every x at which some active cell has a vertex.
      std::vector<double> grid_columns;
      {
        std::vector<double> local;
        for (const auto &cell : soil->triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              local.push_back(cell->vertex(v)[0]);
        for (const auto &part : dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
          grid_columns.insert(grid_columns.end(), part.begin(), part.end());
        std::sort(grid_columns.begin(), grid_columns.end());
        // Vertices closer than a thousandth of the finest cell are the same column.
        std::vector<double> unique{grid_columns.front()};
        for (const double x : grid_columns)
          if (x > unique.back() + 1e-3 * cell_size)
            unique.push_back(x);
        grid_columns = std::move(unique);
      }

      const water::WaterMesh mesh
        = configured_mesh ? *configured_mesh : water::WaterMesh(grid_columns);
      // Soil columns: the grid columns themselves, or, under an independent water mesh,
      // uniform columns of the finest cell size.
      std::vector<double> columns;
      if (!configured_mesh)
        columns = mesh.interfaces();
      else
        {
          const unsigned int n = static_cast<unsigned int>(std::round((right - left) / cell_size));
          for (unsigned int c = 0; c <= n; ++c)
            columns.push_back(c == n ? right : left + c * cell_size);
        }
      std::vector<double> terrain_at_columns;
      for (unsigned int c = 0; c + 1 < columns.size(); ++c)
        {
          const double x = 0.5 * (columns[c] + columns[c + 1]);
          terrain_at_columns.push_back(terrain.value(x, scene.start_time));
          if (!std::isfinite(terrain_at_columns.back()))
            throw InputError("Shallow water/Bed",
                             "B(" + to_string(x) + ")",
                             "a bed elevation that is finite everywhere");
        }
      water     = std::make_unique<water::ShallowWater1D>(mesh,
                                                      water_parameters,
                                                      boundaries[0],
                                                      boundaries[1]);
      interface = std::make_unique<SoilWaterInterface>(columns,
                                                       mesh,
                                                       terrain_at_columns,
                                                       terrain.sample(mesh, scene.start_time),
                                                       coupling.water_density,
                                                       coupling.soil_surface,
                                                       soil_parameters.lower_left[1]);
      set_initial_water();
      if (coupling.loads_on_soil)
        interface->apply_water_loads(*soil, *water, 0.);
    }



    void
    CoupledScene::set_initial_water()
    {
      interface->update_surface(*soil);
      const std::vector<double> &bed = interface->bed();
      water->set_bed(bed);
      std::vector<double> depth, discharge;
      initial_condition.evaluate(water->mesh(), bed, scene.start_time, depth, discharge);
      water->set_state(depth, discharge);
    }



    void
    CoupledScene::exchange_bed()
    {
      interface->update_surface(*soil);
      water->set_bed(interface->bed());
    }



    double
    CoupledScene::free_surface_deviation() const
    {
      double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
      for (unsigned int i = 0; i < water->n_cells(); ++i)
        if (water->depth()[i] > water_parameters.dry_depth)
          {
            const double eta = water->depth()[i] + water->bed()[i];
            lowest           = std::min(lowest, eta);
            highest          = std::max(highest, eta);
          }
      return highest >= lowest ? highest - lowest : 0.;
    }



    void
    CoupledScene::check_state(const unsigned int step,
                              const double       time,
                              const bool         check_soil) const
    {
      const std::string where
        = "at step " + std::to_string(step) + ", t = " + to_string(time) + " s: ";
      const unsigned int bad = water->find_invalid_cell();
      if (bad < water->n_cells())
        throw RunFailure(where + water->describe_invalid_cell(bad));
      if (check_soil)
        {
          const std::string problem = soil->find_invalid_particle();
          if (!problem.empty())
            throw RunFailure(where + problem);
        }
    }



    void
    CoupledScene::add_statistics(Statistics        &statistics,
                                 const unsigned int step,
                                 const double       time,
                                 const double       dt,
                                 const unsigned int soil_steps,
                                 const unsigned int water_steps) const
    {
      const auto   integrals = soil->integrals();
      const double volume    = water->water_volume();
      statistics.add_value("time", time);
      statistics.add_value("step", step);
      statistics.add_value("dt", dt);
      // Steps of each solver in this coupled step (more than one when it sub-cycles).
      statistics.add_value("soil_steps", soil_steps);
      statistics.add_value("water_steps", water_steps);
      statistics.add_value("runout", integrals.runout - initial_toe);
      statistics.add_value("max_free_surface", water->max_free_surface());
      statistics.add_value("max_soil_speed", integrals.max_speed);
      statistics.add_value("max_water_speed", water->max_speed());
      statistics.add_value("water_volume", volume);
      statistics.add_value("water_volume_balance",
                           volume - initial_volume - water->net_boundary_inflow());
      statistics.add_value("soil_mass", integrals.mass);
      statistics.add_value("soil_kinetic_energy", integrals.kinetic_energy);
      const dealii::Tensor<1, 2> load
        = coupling.loads_on_soil ? interface->load_on_soil() : dealii::Tensor<1, 2>();
      statistics.add_value("water_load_x", load[0]);
      statistics.add_value("water_load_y", load[1]);
    }



    void
    CoupledScene::write_output(const unsigned int index, const double time)
    {
      particle_output.write(*soil, index, time);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          char name[64];
          std::snprintf(name, sizeof(name), "/water/profile-%05u.csv", index);
          water::write_profile(*water, scene.output_directory + name, time);
        }
    }



    bool
    CoupledScene::run()
    {
      return run_with_timer(scene.test_mode,
                            [this](dealii::TimerOutput &timer) { return run_time_loop(timer); });
    }



    bool
    CoupledScene::run_time_loop(dealii::TimerOutput &timer)
    {
      using dealii::TimerOutput;
      const bool is_writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      const bool test_mode = scene.test_mode;
      dealii::ConditionalOStream pcout(std::cout, is_writer && !test_mode);
      if (is_writer)
        {
          std::filesystem::create_directories(scene.output_directory + "/particles");
          std::filesystem::create_directories(scene.output_directory + "/water");
        }
      MPI_Barrier(MPI_COMM_WORLD);

      {
        TimerOutput::Scope scope(timer, "coupled: setup");
        soil = std::make_unique<mpm::MaterialPointSolver>(soil_parameters);
        soil->set_timer(timer);
        soil->setup(scene.start_time, [this]() { setup_water(); });
        // The soil may have settled under gravity loading: the water starts over the bed
        // it left, at the initial condition.
        set_initial_water();
        if (coupling.loads_on_soil)
          interface->apply_water_loads(*soil, *water, 0.);
      }
      if (soil_parameters.fixed_time_step > 0.)
        {
          const double limit = mpm::max_time_step_multiplier * soil->stability_limit();
          if (soil_parameters.fixed_time_step > limit)
            throw InputError("Material points/Fixed time step",
                             to_string(soil_parameters.fixed_time_step),
                             "a time step at most the stability limit of this scene, h / "
                             "(sqrt(2) max(c_p + |v_p|)) = "
                               + to_string(limit) + " s");
        }
      initial_volume = water->water_volume();
      initial_toe    = soil->integrals().runout;

      pcout << "Coupled: " << soil->particles().n_global_particles() << " material points on "
            << soil->triangulation().n_global_active_cells() << " cells; " << water->n_cells()
            << " water cells ("
            << (coupling.water_cells == WaterCells::grid_columns ? "grid columns" : "water mesh")
            << ", widths " << water->mesh().min_width() << " to " << water->mesh().max_width()
            << " m); output in " << scene.output_directory << std::endl;

      Statistics statistics;
      statistics.open(scene.output_directory + "/statistics.csv",
                      is_writer,
                      is_writer && test_mode ? &std::cout : nullptr);
      gauges.open(scene.output_directory + "/water/gauges.csv", is_writer);
      ProgressReporter progress(is_writer && !test_mode ? &std::cout : nullptr,
                                scene.start_time,
                                scene.end_time);

      const double end_time       = scene.end_time;
      const double time_tolerance = 1e-12 * (end_time - scene.start_time);
      double       time           = scene.start_time;
      unsigned int step = 0, output_index = 0;
      double next_output = scene.output_interval > 0. ? time + scene.output_interval : end_time;
      double max_volume_balance = 0., max_deviation = free_surface_deviation(),
             max_soil_speed = soil->integrals().max_speed;

      if (!test_mode)
        {
          TimerOutput::Scope scope(timer, "coupled: output");
          write_output(output_index, time);
        }
      ++output_index;
      gauges.record(time, *water);
      add_statistics(statistics, step, time, 0., 0, 0);
      statistics.end_row();

      while (time < end_time - time_tolerance)
        {
          // Eq. 38, or the larger step with the other solver sub-cycling inside it.
          double dt_soil, dt_water;
          {
            TimerOutput::Scope scope(timer, "coupled: time step");
            dt_soil  = soil->stable_time_step();
            dt_water = water->stable_time_step();
          }
          if (scene.maximum_time_step > 0.)
            {
              dt_soil  = std::min(dt_soil, scene.maximum_time_step);
              dt_water = std::min(dt_water, scene.maximum_time_step);
            }
          const unsigned int N      = coupling.maximum_substeps;
          double             dt     = dt_soil <= dt_water ? std::min(dt_water, N * dt_soil) :
                                                            std::min(dt_soil, N * dt_water);
          const double       target = std::min(next_output, end_time);
          const bool         reaches_target = time + dt >= target - time_tolerance;
          if (reaches_target)
            dt = target - time;
          const auto substeps = [&](const double limit) {
            return static_cast<unsigned int>(std::max(1., std::ceil(dt / limit * (1. - 1e-12))));
          };
          const unsigned int n_soil = substeps(dt_soil);

          {
            TimerOutput::Scope scope(timer, "coupled: soil");
            for (unsigned int k = 0; k < n_soil; ++k)
              soil->advance(dt / n_soil);
          }
          {
            TimerOutput::Scope scope(timer, "coupled: bed from soil");
            exchange_bed();
          }
          // The water covers the same interval, in steps of its own CFL limit (one step
          // unless it sub-cycles).
          unsigned int n_water   = 0;
          double       last_step = dt;
          {
            TimerOutput::Scope scope(timer, "coupled: water");
            for (double t = time; t < time + dt * (1. - 1e-12); ++n_water)
              {
                const double limit = n_water == 0 ? dt_water : water->stable_time_step();
                last_step          = std::min(limit, time + dt - t);
                if (time + dt - t - last_step < 1e-12 * dt)
                  last_step = time + dt - t;
                water->advance(t, last_step);
                t += last_step;
              }
          }
          time = reaches_target ? target : time + dt;
          ++step;

          const bool is_output_time = reaches_target && target == next_output;
          const bool at_end         = time >= end_time - time_tolerance;
          const bool reports = is_output_time || at_end || step % scene.statistics_interval == 0;
          {
            TimerOutput::Scope scope(timer, "coupled: checks");
            check_state(step, time, step % check_interval == 0 || reports);
          }
          if (coupling.loads_on_soil)
            {
              TimerOutput::Scope scope(timer, "coupled: water loads on soil");
              interface->apply_water_loads(*soil, *water, last_step);
            }

          if (coupling.tolerance_volume > 0.)
            max_volume_balance = std::max(max_volume_balance,
                                          std::abs(water->water_volume() - initial_volume
                                                   - water->net_boundary_inflow())
                                            / initial_volume);
          if (coupling.tolerance_free_surface > 0.)
            max_deviation = std::max(max_deviation, free_surface_deviation());
          if (coupling.tolerance_soil_speed > 0.)
            max_soil_speed = std::max(max_soil_speed, soil->integrals().max_speed);

          {
            TimerOutput::Scope scope(timer, "coupled: output");
            gauges.record(time, *water);
            if (is_output_time || at_end)
              {
                if (!test_mode)
                  write_output(output_index, time);
                ++output_index;
                if (is_output_time)
                  next_output
                    = scene.output_interval > 0. ? next_output + scene.output_interval : end_time;
              }
            if (reports)
              {
                add_statistics(statistics, step, time, dt, n_soil, n_water);
                statistics.end_row();
              }
          }
          progress.report(step, time, dt, at_end);
        }
      gauges.flush();

      bool       within = true;
      const auto check  = [&](const char *what, const double value, const double tolerance) {
        if (tolerance <= 0.)
          return;
        const bool ok = value <= tolerance;
        within        = within && ok;
        if (is_writer)
          std::cout << what << " = " << format("%.3e", value) << " <= " << format("%.3e", tolerance)
                    << ": " << (ok ? "yes" : "no") << std::endl;
      };
      check("Largest relative water volume balance error",
            max_volume_balance,
            coupling.tolerance_volume);
      check("Largest free-surface deviation from flat [m]",
            max_deviation,
            coupling.tolerance_free_surface);
      check("Largest soil speed [m/s]", max_soil_speed, coupling.tolerance_soil_speed);
      return within;
    }
  } // namespace coupling
} // namespace slidewave
