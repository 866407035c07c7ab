#include <cmath>
#include <cstdio>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <slidewave/core/format.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/run_control.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/water/water_checkpoint.h>
#include <slidewave/water/water_output.h>
#include <slidewave/water/water_scene.h>
#include <sstream>
#include <utility>

namespace slidewave
{
  namespace water
  {
    namespace
    {
      const std::string section = "Shallow water";
    } // namespace



    void
    WaterScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection(section);
      {
        ShallowWaterParameters::declare_parameters(prm);

        prm.enter_subsection("Mesh");
        WaterMesh::declare_parameters(prm);
        prm.leave_subsection();

        prm.enter_subsection("Bed");
        BedElevation::declare_parameters(prm);
        prm.leave_subsection();

        prm.enter_subsection("Initial condition");
        InitialCondition::declare_parameters(prm);
        prm.leave_subsection();

        for (const std::string end : {"Left boundary", "Right boundary"})
          {
            prm.enter_subsection(end);
            WaterBoundary::declare_parameters(prm);
            prm.leave_subsection();
          }

        prm.enter_subsection("Gauges");
        prm.declare_entry("Positions",
                          "",
                          Anything(),
                          "Comma-separated positions x [m] where the free surface is "
                          "recorded every step into water/gauges.csv.");
        prm.leave_subsection();

        prm.enter_subsection("Verification");
        {
          prm.declare_entry("Exact solution",
                            "none",
                            Selection("none|dam break|initial state|thacker|still level"),
                            "Exact solution to measure the error against at the end. 'dam "
                            "break': Stoker (wet bed) or Ritter (Right depth = 0). 'initial "
                            "state': a steady state (lake at rest, uniform flow). 'thacker': "
                            "planar surface in a parabolic bowl. 'still level': water at rest "
                            "under a flat free surface at the level that the water volume "
                            "gives over the current bed, (V + sum B dx) / L, everywhere wet "
                            "(the quasi-static limit under a slowly moving bed).");
          prm.declare_entry("Left depth", "1", Double(0.), "Dam break: depth left of the dam [m].");
          prm.declare_entry("Right depth",
                            "0.5",
                            Double(0.),
                            "Dam break: depth right of the dam [m]; 0 for a dry bed.");
          prm.declare_entry("Dam position", "0.5", Double(), "Dam break: position of the dam [m].");
          prm.declare_entry("Bowl depth", "4", Double(0.), "Thacker: D0 [m].");
          prm.declare_entry("Bowl half width", "10", Double(0.), "Thacker: L [m].");
          prm.declare_entry("Amplitude", "2", Double(0.), "Thacker: A [m].");
          prm.declare_entry("Tolerance on L1 depth error",
                            "0",
                            Double(0.),
                            "If > 0, the run fails (exit status 3) when the L1 depth error "
                            "exceeds it.");
          prm.declare_entry("Tolerance on maximum errors",
                            "0",
                            Double(0.),
                            "If > 0, the run fails (exit status 3) when the maximum error of "
                            "the free surface or of the discharge exceeds it.");
          prm.declare_entry("Tolerance on volume balance",
                            "0",
                            Double(0.),
                            "If > 0, the run fails (exit status 3) when, at any step, the "
                            "water volume differs from the initial volume plus the boundary "
                            "inflow by more than this fraction of the initial volume.");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    WaterScene::WaterScene(const SceneParameters &scene_parameters, dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , is_writer(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      , water_directory(scene_parameters.output_directory + "/water")
    {
      prm.enter_subsection(section);

      ShallowWaterParameters solver_parameters;
      solver_parameters.parse_parameters(prm, section);

      prm.enter_subsection("Mesh");
      const WaterMesh mesh = WaterMesh::from_parameters(prm, section + "/Mesh");
      prm.leave_subsection();

      WaterBoundary boundaries[2];
      const char   *ends[2] = {"Left boundary", "Right boundary"};
      for (unsigned int e = 0; e < 2; ++e)
        {
          prm.enter_subsection(ends[e]);
          boundaries[e].parse_parameters(prm, section + "/" + ends[e], scene);
          prm.leave_subsection();
        }

      water
        = std::make_unique<ShallowWater1D>(mesh, solver_parameters, boundaries[0], boundaries[1]);
      const unsigned int n = mesh.n_cells();

      // The bed, sampled at cell centres.
      prm.enter_subsection("Bed");
      BedElevation bed_elevation;
      bed_elevation.parse_parameters(prm, section + "/Bed", scene);
      prm.leave_subsection();
      const std::vector<double> bed = bed_elevation.sample(mesh, scene.start_time);
      if (bed_elevation.time_dependent())
        {
          moving_bed = std::make_unique<BedElevation>(std::move(bed_elevation));
          bed_work.resize(n);
        }
      water->set_bed(bed);

      // The initial state.
      std::vector<double> depth, discharge;
      prm.enter_subsection("Initial condition");
      {
        InitialCondition initial_condition;
        initial_condition.parse_parameters(prm, section + "/Initial condition");
        initial_condition.evaluate(mesh, bed, scene.start_time, depth, discharge);
      }
      prm.leave_subsection();
      water->set_state(depth, discharge);
      initial_depth     = water->depth();
      initial_discharge = water->discharge();

      prm.enter_subsection("Gauges");
      gauges.parse_positions(section + "/Gauges/Positions",
                             prm.get("Positions"),
                             mesh.left_end(),
                             mesh.right_end());
      prm.leave_subsection();

      parse_verification(prm, solver_parameters.gravity);

      prm.leave_subsection();
      initial_volume = water->water_volume();
    }



    void
    WaterScene::parse_verification(dealii::ParameterHandler &prm, const double gravity)
    {
      prm.enter_subsection("Verification");
      {
        const std::string type = prm.get("Exact solution");
        tolerance_volume       = prm.get_double("Tolerance on volume balance");
        tolerance_l1_depth     = prm.get_double("Tolerance on L1 depth error");
        tolerance_linf         = prm.get_double("Tolerance on maximum errors");
        if (type == "dam break")
          {
            exact_solution   = ExactSolution::dam_break;
            const double h_l = prm.get_double("Left depth");
            const double h_r = prm.get_double("Right depth");
            if (!(h_l > h_r))
              throw InputError(section + "/Verification/Right depth",
                               to_string(h_r),
                               "a depth smaller than 'Left depth' = " + to_string(h_l));
            dam_break.emplace(h_l, h_r, prm.get_double("Dam position"), gravity);
          }
        else if (type == "initial state")
          exact_solution = ExactSolution::initial_state;
        else if (type == "still level")
          exact_solution = ExactSolution::still_level;
        else if (type == "thacker")
          {
            exact_solution = ExactSolution::thacker;
            thacker.emplace(prm.get_double("Bowl depth"),
                            prm.get_double("Bowl half width"),
                            prm.get_double("Amplitude"),
                            gravity);
          }
      }
      prm.leave_subsection();
    }



    void
    WaterScene::exact_state(const double x,
                            const double time,
                            double      &depth,
                            double      &discharge) const
    {
      double velocity = 0.;
      switch (exact_solution)
        {
          case ExactSolution::dam_break:
            dam_break->evaluate(x, time - scene.start_time, depth, velocity);
            break;
          case ExactSolution::thacker:
            thacker->evaluate(x, time, depth, velocity);
            break;
            default: {
              const unsigned int i = water->mesh().cell_containing(x);
              depth                = initial_depth[i];
              velocity             = depth > 0. ? initial_discharge[i] / depth : 0.;
            }
        }
      discharge = depth * velocity;
    }



    bool
    WaterScene::report_errors(const double time) const
    {
      if (exact_solution == ExactSolution::none)
        return true;
      const WaterMesh &mesh = water->mesh();
      const auto      &bed  = water->bed();
      // 'still level': the flat surface that the water volume gives over the current bed.
      double still_level = 0.;
      if (exact_solution == ExactSolution::still_level)
        {
          double bed_volume = 0.;
          for (unsigned int i = 0; i < mesh.n_cells(); ++i)
            bed_volume += bed[i] * mesh.width(i);
          still_level = (water->water_volume() + bed_volume)
                        / (mesh.interfaces().back() - mesh.interfaces().front());
        }
      double l1_depth = 0., l1_velocity = 0., linf_eta = 0., linf_discharge = 0.;
      for (unsigned int i = 0; i < mesh.n_cells(); ++i)
        {
          double h_exact, q_exact;
          if (exact_solution == ExactSolution::still_level)
            {
              h_exact = std::max(still_level - bed[i], 0.);
              q_exact = 0.;
            }
          else
            exact_state(mesh.center(i), time, h_exact, q_exact);
          const double u_exact = h_exact > 0. ? q_exact / h_exact : 0.;
          const double h       = water->depth()[i];
          l1_depth += std::abs(h - h_exact) * mesh.width(i);
          l1_velocity += std::abs(water->velocity(i) - u_exact) * mesh.width(i);
          // The free surface where there is water; the depth where the exact state is dry.
          linf_eta       = std::max(linf_eta, std::abs((h + bed[i]) - (h_exact + bed[i])));
          linf_discharge = std::max(linf_discharge, std::abs(water->discharge()[i] - q_exact));
        }

      bool within = true;
      if (is_writer)
        {
          std::ostream &out = std::cout;
          out << "Error against the exact solution at t = " << format("%.6f", time) << ":\n"
              << "  L1 error depth          = " << format("%.8e", l1_depth) << " m^2\n"
              << "  L1 error velocity       = " << format("%.8e", l1_velocity) << " m^2/s\n"
              << "  max error free surface  = " << format("%.3e", linf_eta) << " m\n"
              << "  max error discharge     = " << format("%.3e", linf_discharge) << " m^2/s\n";
          std::ofstream csv(water_directory + "/errors.csv");
          csv.precision(12);
          csv << "time,cells,l1_depth,l1_velocity,max_free_surface,max_discharge\n"
              << time << ',' << mesh.n_cells() << ',' << l1_depth << ',' << l1_velocity << ','
              << linf_eta << ',' << linf_discharge << '\n';
          csv.close();
          require_written(csv, water_directory + "/errors.csv");
        }
      if (tolerance_l1_depth > 0.)
        {
          const bool ok = l1_depth <= tolerance_l1_depth;
          within        = within && ok;
          if (is_writer)
            std::cout << "  L1 error depth <= " << format("%.3e", tolerance_l1_depth) << ": "
                      << (ok ? "yes" : "no") << '\n';
        }
      if (tolerance_linf > 0.)
        {
          const bool ok = linf_eta <= tolerance_linf && linf_discharge <= tolerance_linf;
          within        = within && ok;
          if (is_writer)
            std::cout << "  max errors <= " << format("%.3e", tolerance_linf) << ": "
                      << (ok ? "yes" : "no") << '\n';
        }
      return within;
    }



    void
    WaterScene::write_profile(const unsigned int index, const double time) const
    {
      if (!is_writer)
        return;
      char name[64];
      std::snprintf(name, sizeof(name), "/profile-%05u.csv", index);
      water::write_profile(*water, water_directory + name, time);
    }



    bool
    WaterScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return RunControl(scene).run(*this, timer);
      });
    }



    core::MemoryEstimate
    WaterScene::memory_estimate() const
    {
      core::MemoryEstimate estimate;
      estimate.add("water cells",
                   water->n_cells(),
                   core::MemoryEstimate::bytes_per_water_cell,
                   section + "/Mesh",
                   std::to_string(water->n_cells()) + " cells");
      return estimate;
    }



    std::vector<core::OutputFolder>
    WaterScene::output_folders() const
    {
      return {{"water", "the water's profiles and gauges"}};
    }



    void
    WaterScene::set_up(double, dealii::TimerOutput &timer_output)
    {
      // The mesh, the bed and the initial state were built with the scene.
      timer = &timer_output;
      gauges.open(water_directory + "/gauges.csv", is_writer);
    }



    std::string
    WaterScene::description() const
    {
      std::ostringstream line;
      line << "Shallow water: " << water->n_cells() << " cells on [" << water->mesh().left_end()
           << ", " << water->mesh().right_end() << "] m, widths " << water->mesh().min_width()
           << " to " << water->mesh().max_width() << " m; output in " << scene.output_directory;
      return line.str();
    }



    void
    WaterScene::start(const StepInfo &info)
    {
      gauges.record(info.time, *water);
    }



    double
    WaterScene::stable_time_step()
    {
      dealii::TimerOutput::Scope scope(*timer, "water: advance");
      return water->stable_time_step();
    }



    void
    WaterScene::advance(const StepInfo &info)
    {
      if (moving_bed)
        {
          dealii::TimerOutput::Scope scope(*timer, "water: bed update");
          for (unsigned int i = 0; i < bed_work.size(); ++i)
            {
              bed_work[i] = moving_bed->value(water->mesh().center(i), info.time);
              if (!std::isfinite(bed_work[i]))
                throw RunFailure("at step " + std::to_string(info.step)
                                 + ", t = " + to_string(info.time)
                                 + " s: the moving bed B(x, t) is not finite at x = "
                                 + to_string(water->mesh().center(i)) + " m");
            }
          water->set_bed(bed_work);
        }
      dealii::TimerOutput::Scope scope(*timer, "water: advance");
      water->advance(info.old_time, info.dt);
    }



    void
    WaterScene::after_step(const StepInfo &info)
    {
      const unsigned int bad = water->find_invalid_cell();
      if (bad < water->n_cells())
        throw RunFailure("at step " + std::to_string(info.step) + ", t = " + to_string(info.time)
                         + " s: " + water->describe_invalid_cell(bad));

      if (tolerance_volume > 0.)
        max_volume_balance
          = std::max(max_volume_balance,
                     std::abs(water->water_volume() - initial_volume - water->net_boundary_inflow())
                       / initial_volume);
      dealii::TimerOutput::Scope scope(*timer, "water: output");
      gauges.record(info.time, *water);
    }



    void
    WaterScene::write_output(const unsigned int index, const double time)
    {
      dealii::TimerOutput::Scope scope(*timer, "water: output");
      write_profile(index, time);
    }



    bool
    WaterScene::finish(const StepInfo &info)
    {
      gauges.flush();
      if (is_writer && !scene.test_mode)
        std::cout << "Finished " << info.step << " steps; water volume changed by "
                  << format("%.3e",
                            water->water_volume() - initial_volume - water->net_boundary_inflow())
                  << " m^2 beyond the boundary inflow." << std::endl;
      bool within = report_errors(info.time);
      if (tolerance_volume > 0.)
        {
          const bool ok = max_volume_balance <= tolerance_volume;
          within        = within && ok;
          if (is_writer)
            std::cout << "Largest relative water volume balance error = "
                      << format("%.3e", max_volume_balance)
                      << " <= " << format("%.3e", tolerance_volume) << ": " << (ok ? "yes" : "no")
                      << '\n';
        }
      return within;
    }



    std::string
    WaterScene::checkpoint_signature() const
    {
      std::ostringstream out;
      out.precision(12);
      out << "shallow water; " << water->n_cells() << " cells on [" << water->mesh().left_end()
          << ", " << water->mesh().right_end() << "] m";
      return out.str();
    }



    std::vector<std::string>
    WaterScene::growing_files() const
    {
      return {"water/gauges.csv"};
    }



    void
    WaterScene::save(io::CheckpointRecord &record)
    {
      gauges.flush();
      water::save_state(record, "water", *water);
      record.put("water/initial_volume", initial_volume);
      record.put("water/initial_depth", initial_depth);
      record.put("water/initial_discharge", initial_discharge);
      record.put("water/max_volume_balance", max_volume_balance);
    }



    void
    WaterScene::resume(const io::CheckpointRecord &record,
                       const std::string &,
                       dealii::TimerOutput &timer_output)
    {
      timer = &timer_output;
      water::restore_state(record, "water", *water);
      initial_volume     = record.get("water/initial_volume");
      initial_depth      = record.get_vector("water/initial_depth");
      initial_discharge  = record.get_vector("water/initial_discharge");
      max_volume_balance = record.get("water/max_volume_balance");
      gauges.open(water_directory + "/gauges.csv", is_writer, true);
    }



    void
    WaterScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const double volume = water->water_volume();
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      statistics.add_value("water_volume", volume);
      // Volume gained beyond what entered through the ends: zero up to round-off.
      statistics.add_value("water_volume_balance",
                           volume - initial_volume - water->net_boundary_inflow());
      statistics.add_value("max_speed", water->max_speed());
      statistics.add_value("max_free_surface", water->max_free_surface());
    }
  } // namespace water
} // namespace slidewave
