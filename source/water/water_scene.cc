#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/progress_reporter.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/table_1d.h>
#include <slidewave/water/water_scene.h>

#include <cmath>
#include <exception>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <utility>

namespace slidewave
{
  namespace water
  {
    namespace
    {
      const std::string section = "Shallow water";

      std::string
      format(const char *pattern, const double value)
      {
        char buffer[64];
        std::snprintf(buffer, sizeof(buffer), pattern, value);
        return buffer;
      }
    } // namespace



    void
    WaterScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection(section);
      {
        SolverParameters::declare_parameters(prm);

        prm.enter_subsection("Mesh");
        WaterMesh::declare_parameters(prm);
        prm.leave_subsection();

        prm.enter_subsection("Bed");
        {
          prm.declare_entry("Type",
                            "function",
                            Selection("function|table"),
                            "'function': B(x) from 'Function expression'. 'table': from the "
                            "CSV file 'Table file' (x,B), interpolated linearly.");
          prm.declare_entry("Function expression", "0", Anything(),
                            "Bed elevation B(x) [m], an expression of x (and of t with "
                            "'Time dependent').");
          prm.declare_entry("Time dependent", "false", Bool(),
                            "For 'function': the bed moves, B(x, t), re-sampled at the cell "
                            "centres before every step at the step's end time. The water "
                            "depth is kept, so the volume is unchanged and the free surface "
                            "moves with the bed (as under a sliding mass in the coupled "
                            "scenes).");
          prm.declare_entry("Function constants", "", Anything(),
                            "Constants used in the expression, e.g. 'a=0.2, b=0.05'.");
          prm.declare_entry("Table file", "", Anything(),
                            "CSV file x,B for 'table' (relative to the scene file).");
        }
        prm.leave_subsection();

        prm.enter_subsection("Initial condition");
        {
          prm.declare_entry("Variable",
                            "water depth",
                            Selection("water depth|free surface"),
                            "Whether 'Function expression' gives the water depth h or the "
                            "free-surface elevation eta = h + B (then h = max(eta - B, 0)).");
          prm.declare_entry("Function expression", "1", Anything(),
                            "Initial h(x) or eta(x) [m], an expression of x.");
          prm.declare_entry("Velocity expression", "0", Anything(),
                            "Initial velocity u(x) [m/s], an expression of x.");
          prm.declare_entry("Function constants", "", Anything(),
                            "Constants used in both expressions, e.g. 'x0=0.5'.");
        }
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
          prm.declare_entry("Right depth", "0.5", Double(0.),
                            "Dam break: depth right of the dam [m]; 0 for a dry bed.");
          prm.declare_entry("Dam position", "0.5", Double(), "Dam break: position of the dam [m].");
          prm.declare_entry("Bowl depth", "4", Double(0.), "Thacker: D0 [m].");
          prm.declare_entry("Bowl half width", "10", Double(0.), "Thacker: L [m].");
          prm.declare_entry("Amplitude", "2", Double(0.), "Thacker: A [m].");
          prm.declare_entry("Tolerance on L1 depth error", "0", Double(0.),
                            "If > 0, the run fails (exit status 3) when the L1 depth error "
                            "exceeds it.");
          prm.declare_entry("Tolerance on maximum errors", "0", Double(0.),
                            "If > 0, the run fails (exit status 3) when the maximum error of "
                            "the free surface or of the discharge exceeds it.");
          prm.declare_entry("Tolerance on volume balance", "0", Double(0.),
                            "If > 0, the run fails (exit status 3) when, at any step, the "
                            "water volume differs from the initial volume plus the boundary "
                            "inflow by more than this fraction of the initial volume.");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    WaterScene::WaterScene(const SceneParameters &scene_parameters,
                           dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , is_writer(dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      prm.enter_subsection(section);

      SolverParameters solver_parameters;
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

      water = std::make_unique<ShallowWater1D>(mesh, solver_parameters, boundaries[0],
                                               boundaries[1]);
      const unsigned int n = mesh.n_cells();

      // The bed, sampled at cell centres.
      std::vector<double> bed(n);
      prm.enter_subsection("Bed");
      {
        if (prm.get("Type") == "table" && prm.get_bool("Time dependent"))
          throw InputError(section + "/Bed/Time dependent", "true",
                           "false with 'Type = table' (a moving bed is a function B(x, t))");
        if (prm.get("Type") == "table")
          {
            const Table1D table(section + "/Bed/Table file",
                                scene.resolve_path(prm.get("Table file")));
            for (unsigned int i = 0; i < n; ++i)
              bed[i] = table.value(mesh.center(i));
          }
        else
          {
            auto expression =
              std::make_unique<ParsedExpression>(section + "/Bed/Function expression",
                                                 prm.get("Function expression"),
                                                 prm.get("Function constants"));
            for (unsigned int i = 0; i < n; ++i)
              bed[i] = expression->value(mesh.center(i), scene.start_time);
            if (prm.get_bool("Time dependent"))
              {
                moving_bed = std::move(expression);
                bed_work.resize(n);
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          if (!std::isfinite(bed[i]))
            throw InputError(section + "/Bed", "B(" + to_string(mesh.center(i)) + ")",
                             "a bed elevation that is finite everywhere");
      }
      prm.leave_subsection();
      water->set_bed(bed);

      // The initial state.
      std::vector<double> depth(n), discharge(n);
      prm.enter_subsection("Initial condition");
      {
        const std::string path = section + "/Initial condition";
        const std::string constants = prm.get("Function constants");
        const ParsedExpression level(path + "/Function expression",
                                     prm.get("Function expression"), constants);
        const ParsedExpression velocity(path + "/Velocity expression",
                                        prm.get("Velocity expression"), constants);
        const bool is_free_surface = prm.get("Variable") == "free surface";
        for (unsigned int i = 0; i < n; ++i)
          {
            const double x = mesh.center(i);
            const double v = level.value(x, scene.start_time);
            const double u = velocity.value(x, scene.start_time);
            if (!std::isfinite(v) || !std::isfinite(u))
              throw InputError(path + "/Function expression",
                               prm.get("Function expression"),
                               "expressions giving finite values everywhere (not at x = " +
                                 to_string(x) + ")");
            depth[i] = is_free_surface ? std::max(v - bed[i], 0.) : v;
            if (depth[i] < 0.)
              throw InputError(path + "/Function expression",
                               prm.get("Function expression"),
                               "a water depth >= 0 everywhere (it is " + to_string(v) +
                                 " at x = " + to_string(x) + ")");
            discharge[i] = depth[i] * u;
          }
      }
      prm.leave_subsection();
      water->set_state(depth, discharge);
      initial_depth     = water->depth();
      initial_discharge = water->discharge();

      prm.enter_subsection("Gauges");
      {
        const std::string text = prm.get("Positions");
        for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
          {
            double x = 0.;
            try
              {
                std::size_t used = 0;
                x = std::stod(item, &used);
                if (used != item.size())
                  throw std::invalid_argument("");
              }
            catch (const std::exception &)
              {
                throw InputError(section + "/Gauges/Positions", text,
                                 "a comma-separated list of positions");
              }
            if (x < mesh.left_end() || x > mesh.right_end())
              throw InputError(section + "/Gauges/Positions",
                               item,
                               "positions inside the water domain [" +
                                 to_string(mesh.left_end()) + ", " +
                                 to_string(mesh.right_end()) + "]");
            gauge_positions.push_back(x);
          }
      }
      prm.leave_subsection();

      prm.enter_subsection("Verification");
      {
        const std::string type = prm.get("Exact solution");
        const double      g    = solver_parameters.gravity;
        tolerance_volume       = prm.get_double("Tolerance on volume balance");
        tolerance_l1_depth     = prm.get_double("Tolerance on L1 depth error");
        tolerance_linf         = prm.get_double("Tolerance on maximum errors");
        if (type == "dam break")
          {
            exact_solution = ExactSolution::dam_break;
            const double h_l = prm.get_double("Left depth");
            const double h_r = prm.get_double("Right depth");
            if (!(h_l > h_r))
              throw InputError(section + "/Verification/Right depth", to_string(h_r),
                               "a depth smaller than 'Left depth' = " + to_string(h_l));
            dam_break.emplace(h_l, h_r, prm.get_double("Dam position"), g);
          }
        else if (type == "initial state")
          exact_solution = ExactSolution::initial_state;
        else if (type == "still level")
          exact_solution = ExactSolution::still_level;
        else if (type == "thacker")
          {
            exact_solution = ExactSolution::thacker;
            thacker.emplace(prm.get_double("Bowl depth"), prm.get_double("Bowl half width"),
                            prm.get_double("Amplitude"), g);
          }
      }
      prm.leave_subsection();

      prm.leave_subsection();
      initial_volume = water->water_volume();
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
          default:
            {
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
          still_level = (water->water_volume() + bed_volume) /
                        (mesh.interfaces().back() - mesh.interfaces().front());
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
              << "  max error discharge     = " << format("%.3e", linf_discharge)
              << " m^2/s\n";
          std::ofstream csv(water_directory + "/errors.csv");
          csv.precision(12);
          csv << "time,cells,l1_depth,l1_velocity,max_free_surface,max_discharge\n"
              << time << ',' << mesh.n_cells() << ',' << l1_depth << ',' << l1_velocity << ','
              << linf_eta << ',' << linf_discharge << '\n';
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
      std::ofstream out(water_directory + name);
      out.precision(12);
      out << "# time = " << time << "\nx,h,u,hu,bed,eta\n";
      const WaterMesh &mesh = water->mesh();
      for (unsigned int i = 0; i < mesh.n_cells(); ++i)
        {
          const double h = water->depth()[i];
          const double b = water->bed()[i];
          out << mesh.center(i) << ',' << h << ',' << water->velocity(i) << ','
              << water->discharge()[i] << ',' << b << ',' << h + b << '\n';
        }
    }



    void
    WaterScene::write_gauges(const double time)
    {
      if (gauge_file == nullptr)
        return;
      *gauge_file << time;
      for (const double x : gauge_positions)
        *gauge_file << ',' << water->free_surface_at(x);
      *gauge_file << '\n';
    }



    bool
    WaterScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return run_time_loop(timer);
      });
    }



    bool
    WaterScene::run_time_loop(dealii::TimerOutput &timer)
    {
      using dealii::TimerOutput;
      const bool         test_mode = scene.test_mode;
      dealii::ConditionalOStream pcout(std::cout, is_writer && !test_mode);

      water_directory = scene.output_directory + "/water";
      if (is_writer)
        std::filesystem::create_directories(water_directory);

      pcout << "Shallow water: " << water->n_cells() << " cells on ["
            << water->mesh().left_end() << ", " << water->mesh().right_end()
            << "] m, widths " << water->mesh().min_width() << " to "
            << water->mesh().max_width() << " m; output in " << scene.output_directory
            << std::endl;

      Statistics statistics;
      statistics.open(scene.output_directory + "/statistics.csv", is_writer,
                      is_writer && test_mode ? &std::cout : nullptr);

      if (is_writer && !gauge_positions.empty())
        {
          gauge_stream = std::make_unique<std::ofstream>(water_directory + "/gauges.csv");
          gauge_file   = gauge_stream.get();
          gauge_file->precision(12);
          *gauge_file << "time";
          for (const double x : gauge_positions)
            *gauge_file << ",eta(x=" << x << ")";
          *gauge_file << '\n';
        }

      ProgressReporter progress(is_writer && !test_mode ? &std::cout : nullptr,
                                scene.start_time, scene.end_time);

      double       time         = scene.start_time;
      unsigned int step         = 0;
      unsigned int output_index = 0;
      double       dt           = 0.;
      const double end_time     = scene.end_time;
      const double time_tolerance = 1e-12 * (end_time - scene.start_time);
      double       max_volume_balance = 0.;
      double       next_output = scene.output_interval > 0. ?
                                   scene.start_time + scene.output_interval :
                                   end_time;

      write_profile(output_index++, time);
      write_gauges(time);
      add_statistics(statistics, step, time, dt);
      statistics.end_row();

      while (time < end_time - time_tolerance)
        {
          {
            TimerOutput::Scope scope(timer, "water: advance");
            dt = water->stable_time_step();
          }
          if (scene.maximum_time_step > 0.)
            dt = std::min(dt, scene.maximum_time_step);
          const double target = std::min(next_output, end_time);
          if (!std::isfinite(dt))
            dt = target - time;
          const bool reaches_target = time + dt >= target - time_tolerance;
          if (reaches_target)
            dt = target - time;

          if (moving_bed)
            {
              TimerOutput::Scope scope(timer, "water: bed update");
              const double t_new = reaches_target ? target : time + dt;
              for (unsigned int i = 0; i < bed_work.size(); ++i)
                {
                  bed_work[i] = moving_bed->value(water->mesh().center(i), t_new);
                  if (!std::isfinite(bed_work[i]))
                    throw RunFailure("at step " + std::to_string(step + 1) + ", t = " +
                                     to_string(t_new) + " s: the moving bed B(x, t) is not "
                                     "finite at x = " + to_string(water->mesh().center(i)) +
                                     " m");
                }
              water->set_bed(bed_work);
            }
          {
            TimerOutput::Scope scope(timer, "water: advance");
            water->advance(time, dt);
          }
          time = reaches_target ? target : time + dt;
          ++step;

          const unsigned int bad = water->find_invalid_cell();
          if (bad < water->n_cells())
            {
              const double h = water->depth()[bad], q = water->discharge()[bad];
              throw RunFailure(
                "at step " + std::to_string(step) + ", t = " + to_string(time) +
                " s: " + (std::isfinite(h) && std::isfinite(q) ? "negative water depth" :
                                                                  "non-finite water state") +
                " in water cell " + std::to_string(bad) + " (x = " +
                to_string(water->mesh().center(bad)) + " m): h = " + to_string(h) +
                ", hu = " + to_string(q));
            }

          if (tolerance_volume > 0.)
            max_volume_balance =
              std::max(max_volume_balance,
                       std::abs(water->water_volume() - initial_volume -
                                water->net_boundary_inflow()) /
                         initial_volume);

          {
            TimerOutput::Scope scope(timer, "water: output");
            write_gauges(time);
            const bool is_output_time = reaches_target && target == next_output;
            if (is_output_time)
              {
                write_profile(output_index++, time);
                next_output += scene.output_interval;
                if (scene.output_interval <= 0.)
                  next_output = end_time;
              }
            const bool at_end = time >= end_time - time_tolerance;
            if (at_end && !is_output_time)
              write_profile(output_index++, time);
            if (step % scene.statistics_interval == 0 || is_output_time || at_end)
              {
                add_statistics(statistics, step, time, dt);
                statistics.end_row();
              }
          }
          progress.report(step, time, dt, time >= end_time - time_tolerance);
        }

      if (gauge_file != nullptr)
        gauge_file->flush();

      if (is_writer && !test_mode)
        std::cout << "Finished " << step << " steps; water volume changed by "
                  << format("%.3e", water->water_volume() - initial_volume -
                                      water->net_boundary_inflow())
                  << " m^2 beyond the boundary inflow." << std::endl;
      bool within = report_errors(time);
      if (tolerance_volume > 0.)
        {
          const bool ok = max_volume_balance <= tolerance_volume;
          within        = within && ok;
          if (is_writer)
            std::cout << "Largest relative water volume balance error = "
                      << format("%.3e", max_volume_balance) << " <= "
                      << format("%.3e", tolerance_volume) << ": " << (ok ? "yes" : "no")
                      << '\n';
        }
      return within;
    }



    void
    WaterScene::add_statistics(Statistics        &statistics,
                               const unsigned int step,
                               const double       time,
                               const double       dt) const
    {
      const double volume = water->water_volume();
      statistics.add_value("time", time);
      statistics.add_value("step", step);
      statistics.add_value("dt", dt);
      statistics.add_value("water_volume", volume);
      // Volume gained beyond what entered through the ends: zero up to round-off.
      statistics.add_value("water_volume_balance",
                           volume - initial_volume - water->net_boundary_inflow());
      statistics.add_value("max_speed", water->max_speed());
      statistics.add_value("max_free_surface", water->max_free_surface());
    }
  } // namespace water
} // namespace slidewave
