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
#include <slidewave/core/run_control.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/coupling/coupled_scene.h>
#include <sstream>

namespace slidewave
{
  namespace coupling
  {
    namespace
    {
      const std::string section = "Coupling";
    } // namespace



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
      prm.enter_subsection(section);
      coupling.parse_parameters(prm);
      prm.leave_subsection();

      prm.enter_subsection("Material points");
      soil_parameters.parse_parameters(prm, "Material points");
      check_interval = prm.get_integer("Check interval");
      prm.leave_subsection();
      soil_parameters.point_forces = coupling.loads_on_soil;
      if (!soil_parameters.solids.empty())
        throw InputError(soil_parameters.solids.front().path + "/Type",
                         "solid",
                         "none, roller or fixed with Physics = coupled (the shallow water "
                         "would not see the solid)");

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
      std::vector<double> soil_columns;
      if (!configured_mesh)
        soil_columns = mesh.interfaces();
      else
        {
          const unsigned int n = static_cast<unsigned int>(std::round((right - left) / cell_size));
          for (unsigned int c = 0; c <= n; ++c)
            soil_columns.push_back(c == n ? right : left + c * cell_size);
        }
      build_water(mesh, soil_columns);
      set_initial_water();
      if (coupling.loads_on_soil)
        interface->apply_water_loads(soil_points(), *water, 0.);
    }



    void
    CoupledScene::build_water(const water::WaterMesh &mesh, const std::vector<double> &soil_columns)
    {
      columns = soil_columns;
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
                                                       WaterConstants::of(coupling.water_density,
                                                                          water_parameters),
                                                       soil->property_layout(),
                                                       coupling.soil_surface,
                                                       soil_parameters.lower_left[1],
                                                       coupling.water_pressure);
    }



    void
    CoupledScene::set_initial_water()
    {
      interface->update_surface(soil->particles());
      const std::vector<double> &bed = interface->bed();
      water->set_bed(bed);
      std::vector<double> depth, discharge;
      initial_condition.evaluate(water->mesh(), bed, scene.start_time, depth, discharge);
      water->set_state(depth, discharge);
      // The initial level eta_0 of the excess pressure (paper 000, Eq. 10): the last call,
      // after any gravity loading, decides.
      interface->set_initial_level(*water);
    }



    void
    CoupledScene::exchange_bed()
    {
      interface->update_surface(soil->particles());
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
    CoupledScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const auto   integrals = soil->integrals();
      const double volume    = water->water_volume();
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      // Steps of each solver in this coupled step (more than one when it sub-cycles; zero
      // before the first).
      statistics.add_value("soil_steps", n_soil);
      statistics.add_value("water_steps", n_water);
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
      if (scene.test_mode)
        return;
      dealii::TimerOutput::Scope scope(*timer, "coupled: output");
      particle_output.write(soil->particles(), soil->property_layout(), index, time);
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
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return RunControl(scene).run(*this, timer);
      });
    }



    core::MemoryEstimate
    CoupledScene::memory_estimate() const
    {
      core::MemoryEstimate estimate;
      soil_parameters.add_to_memory_estimate(estimate, "Material points");
      // The water's mesh as configured, else one water cell per column of the grid.
      const auto  &soil = soil_parameters;
      const double n_water
        = configured_mesh ? configured_mesh->n_cells() :
                            std::round((soil.upper_right[0] - soil.lower_left[0]) / soil.cell_size);
      estimate.add("water cells",
                   n_water,
                   core::MemoryEstimate::bytes_per_water_cell,
                   "Shallow water/Mesh",
                   to_string(n_water) + " cells");
      return estimate;
    }



    std::vector<core::OutputFolder>
    CoupledScene::output_folders() const
    {
      return {{"particles", "the material points"}, {"water", "the water"}};
    }



    void
    CoupledScene::create_soil(dealii::TimerOutput &timer_output)
    {
      timer = &timer_output;
      grid  = soil::MaterialPointSolver::make_grid(soil_parameters);
      soil  = std::make_unique<soil::MaterialPointSolver>(soil_parameters, *grid);
      soil->set_timer(timer_output);
    }



    void
    CoupledScene::set_up(const double start_time, dealii::TimerOutput &timer_output)
    {
      {
        dealii::TimerOutput::Scope scope(timer_output, "coupled: setup");
        create_soil(timer_output);
        // The water and its loads on the points come before the soil's initial stress: the
        // geostatic stress carries them, and gravity loading holds them.
        soil->create_points(start_time);
        setup_water();
        soil->initialize_stress();
        // The soil may have settled under gravity loading: the water starts over the bed
        // it left, at the initial condition.
        set_initial_water();
        if (coupling.loads_on_soil)
          interface->apply_water_loads(soil_points(), *water, 0.);
      }
      initial_volume = water->water_volume();
      initial_toe    = soil->integrals().runout;
      gauges.open(scene.output_directory + "/water/gauges.csv",
                  dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);
    }



    void
    CoupledScene::check_set_up() const
    {
      if (soil_parameters.fixed_time_step > 0.)
        {
          const double limit = soil::max_time_step_multiplier * soil->stability_limit();
          if (soil_parameters.fixed_time_step > limit)
            throw InputError("Material points/Fixed time step",
                             to_string(soil_parameters.fixed_time_step),
                             "a time step at most the stability limit of this scene, h / "
                             "(sqrt(2) max(c_p + |v_p|)) = "
                               + to_string(limit) + " s");
        }
    }



    std::string
    CoupledScene::description() const
    {
      std::ostringstream line;
      line << "Coupled: " << soil->particles().n_global_particles() << " material points on "
           << soil->triangulation().n_global_active_cells() << " cells; " << water->n_cells()
           << " water cells ("
           << (coupling.water_cells == WaterCells::grid_columns ? "grid columns" : "water mesh")
           << ", widths " << water->mesh().min_width() << " to " << water->mesh().max_width()
           << " m); output in " << scene.output_directory;
      return line.str();
    }



    void
    CoupledScene::start(const StepInfo &info)
    {
      max_deviation  = free_surface_deviation();
      max_soil_speed = soil->integrals().max_speed;
      gauges.record(info.time, *water);
    }



    double
    CoupledScene::stable_time_step()
    {
      {
        dealii::TimerOutput::Scope scope(*timer, "coupled: time step");
        dt_soil  = soil->stable_time_step();
        dt_water = water->stable_time_step();
      }
      if (scene.maximum_time_step > 0.)
        {
          dt_soil  = std::min(dt_soil, scene.maximum_time_step);
          dt_water = std::min(dt_water, scene.maximum_time_step);
        }
      const unsigned int N = coupling.maximum_substeps;
      return dt_soil <= dt_water ? std::min(dt_water, N * dt_soil) :
                                   std::min(dt_soil, N * dt_water);
    }



    void
    CoupledScene::advance(const StepInfo &info)
    {
      const double time = info.old_time, dt = info.dt;
      n_soil = static_cast<unsigned int>(std::max(1., std::ceil(dt / dt_soil * (1. - 1e-12))));
      {
        dealii::TimerOutput::Scope scope(*timer, "coupled: soil");
        for (unsigned int k = 0; k < n_soil; ++k)
          soil->advance(dt / n_soil);
      }
      {
        dealii::TimerOutput::Scope scope(*timer, "coupled: bed from soil");
        exchange_bed();
      }
      // The water covers the same interval, in steps of its own CFL limit (one step unless
      // it sub-cycles).
      dealii::TimerOutput::Scope scope(*timer, "coupled: water");
      n_water         = 0;
      last_water_step = dt;
      for (double t = time; t < time + dt * (1. - 1e-12); ++n_water)
        {
          const double limit = n_water == 0 ? dt_water : water->stable_time_step();
          last_water_step    = std::min(limit, time + dt - t);
          if (time + dt - t - last_water_step < 1e-12 * dt)
            last_water_step = time + dt - t;
          water->advance(t, last_water_step);
          t += last_water_step;
        }
    }



    void
    CoupledScene::after_step(const StepInfo &info)
    {
      {
        dealii::TimerOutput::Scope scope(*timer, "coupled: checks");
        check_state(info.step, info.time, info.step % check_interval == 0 || info.reports);
      }
      if (coupling.loads_on_soil)
        {
          dealii::TimerOutput::Scope scope(*timer, "coupled: water loads on soil");
          interface->apply_water_loads(soil_points(), *water, last_water_step);
        }
      if (coupling.tolerance_volume > 0.)
        max_volume_balance
          = std::max(max_volume_balance,
                     std::abs(water->water_volume() - initial_volume - water->net_boundary_inflow())
                       / initial_volume);
      if (coupling.tolerance_free_surface > 0.)
        max_deviation = std::max(max_deviation, free_surface_deviation());
      if (coupling.tolerance_soil_speed > 0.)
        max_soil_speed = std::max(max_soil_speed, soil->integrals().max_speed);
      dealii::TimerOutput::Scope scope(*timer, "coupled: output");
      gauges.record(info.time, *water);
    }



    bool
    CoupledScene::finish(const StepInfo &)
    {
      gauges.flush();
      const bool is_writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      bool       within    = true;
      const auto check     = [&](const char *what, const double value, const double tolerance) {
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
