#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/core/run_control.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/fluid/free_surface_diagnostics.h>
#include <slidewave/fluid/free_surface_scene.h>
#include <slidewave/fluid/martin_moyce.h>
#include <slidewave/fluid/standing_wave.h>
#include <slidewave/fluid/velocity_subscales.h>
#include <sstream>

namespace slidewave
{
  namespace fluid
  {
    namespace
    {
      const std::string section = "Free surface flow";

      /** The entries of subsection "Free surface flow", read and checked. */
      FreeSurfaceParameters
      parse(dealii::ParameterHandler &prm)
      {
        FreeSurfaceParameters parameters;
        prm.enter_subsection(section);
        parameters.parse_parameters(prm);
        prm.leave_subsection();
        return parameters;
      }
    } // namespace



    void
    FreeSurfaceScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection(section);
      FreeSurfaceParameters::declare_parameters(prm);
      prm.leave_subsection();
    }



    FreeSurfaceScene::FreeSurfaceScene(const SceneParameters    &scene_parameters,
                                       dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , parameters(parse(prm))
      , output(scene_parameters.output_directory, parameters.gauges, parameters.pressure_probes)
    {
    }



    bool
    FreeSurfaceScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return RunControl(scene).run(*this, timer);
      });
    }



    core::MemoryEstimate
    FreeSurfaceScene::memory_estimate() const
    {
      // At 'Cell size' everywhere (an adaptive grid is finer only near the surface): its
      // cells, and Q1^2-Q1 flow plus Q1 phase field, four unknowns per node.
      const double nx
        = std::round((parameters.upper_right[0] - parameters.lower_left[0]) / parameters.cell_size),
        ny
        = std::round((parameters.upper_right[1] - parameters.lower_left[1]) / parameters.cell_size);
      core::MemoryEstimate estimate;
      estimate.add("grid cells",
                   nx * ny,
                   core::MemoryEstimate::bytes_per_grid_cell,
                   section + "/Grid/Cell size",
                   to_string(parameters.cell_size));
      estimate.add("unknowns",
                   4. * (nx + 1.) * (ny + 1.),
                   core::MemoryEstimate::bytes_per_dof,
                   section + "/Grid/Cell size",
                   to_string(parameters.cell_size));
      fluid::VelocitySubscales::add_to_memory_estimate(estimate, parameters, section, nx * ny);
      // Where each cell's entries and values sit in the flow's and the phase field's
      // matrices and vectors (linear_algebra::CellScatter, CellGather): 12^2 + 4^2
      // positions of 2 bytes and 12 + 4 rows, right-hand side and vector positions of
      // 4 bytes, each system reading the other's vectors too.
      estimate.add("grid cells' assembly positions",
                   nx * ny,
                   (144. + 16.) * 2. + (12. + 4.) * 4. * 4.,
                   section + "/Grid/Cell size",
                   to_string(parameters.cell_size));
      return estimate;
    }



    std::vector<core::OutputFolder>
    FreeSurfaceScene::output_folders() const
    {
      return {{"free_surface", "the flow's fields"}};
    }



    void
    FreeSurfaceScene::create_solver()
    {
      grid   = FreeSurfaceSolver::make_grid(parameters);
      solver = std::make_unique<FreeSurfaceSolver>(parameters, *grid);
    }



    void
    FreeSurfaceScene::set_up(const double start_time, dealii::TimerOutput &timer_output)
    {
      timer = &timer_output;
      dealii::TimerOutput::Scope scope(timer_output, "fluid: setup");
      create_solver();
      solver->setup(start_time);
      balance.start(solver->water_volume());
      output.open_gauges(false);
    }



    void
    FreeSurfaceScene::check_set_up() const
    {
      // The first step is the largest the flow will allow (the water starts at rest); a
      // scene that would need more than 10^7 of them is a mistake in Courant number, time
      // step or end time, not a run anyone waits for.
      core::check_step_count(scene,
                             solver->stable_time_step(),
                             section + "/Time stepping/Maximum time step",
                             to_string(parameters.maximum_time_step),
                             "with 'Courant number' = " + to_string(parameters.courant_number)
                               + ", the first step");
    }



    std::string
    FreeSurfaceScene::description() const
    {
      return "Free surface flow: " + std::to_string(grid->triangulation().n_global_active_cells())
             + " cells, " + std::to_string(solver->flow_field().dof_handler().n_dofs())
             + " flow and " + std::to_string(solver->phase_field().dof_handler().n_dofs())
             + " phase-field unknowns; output in " + scene.output_directory;
    }



    void
    FreeSurfaceScene::start(const StepInfo &info)
    {
      output.record_gauges(*solver, info.time);
      if (parameters.exact_solution == FlowExactSolution::martin_moyce
          || parameters.exact_solution == FlowExactSolution::standing_wave)
        verification_history.emplace_back(info.time, verification_value());
    }



    double
    FreeSurfaceScene::stable_time_step()
    {
      return solver->stable_time_step();
    }



    void
    FreeSurfaceScene::advance(const StepInfo &info)
    {
      dealii::TimerOutput::Scope scope(*timer, "fluid: advance");
      last_report = solver->advance(info.dt);
      part_times[0] += last_report.flow.assembly_time;
      part_times[1] += last_report.flow.preconditioner_time;
      part_times[2] += last_report.flow.solve_time;
      part_times[3] += last_report.phase.assembly_time + last_report.phase.solve_time;
      flow_iterations += last_report.flow.iterations;
      preconditioner_builds += last_report.flow.preconditioner_time > 0. ? 1 : 0;
    }



    std::string
    FreeSurfaceScene::check_state(const StepInfo &info) const
    {
      const std::string where
        = "at step " + std::to_string(info.step) + ", t = " + to_string(info.time) + " s: ";
      if (!solver->state_is_finite())
        throw RunFailure(where
                         + "the velocity, pressure or phase field is not finite (reduce "
                           "'Time stepping/Courant number' or 'Maximum time step')");
      const double speed = solver->max_speed();
      if (parameters.max_speed > 0. && speed > parameters.max_speed)
        throw RunFailure(where + "the largest speed, " + to_string(speed)
                         + " m/s, exceeds 'Free surface flow/Guards/Maximum speed' = "
                         + to_string(parameters.max_speed) + " m/s");
      return where;
    }



    void
    FreeSurfaceScene::after_step(const StepInfo &info)
    {
      dealii::TimerOutput::Scope scope(*timer, "fluid: checks and gauges");
      const std::string          where = check_state(info);
      balance.check(where, solver->water_volume(), solver->water_outflow);
      output.record_gauges(*solver, info.time);
      if (parameters.exact_solution == FlowExactSolution::martin_moyce
          || parameters.exact_solution == FlowExactSolution::standing_wave)
        verification_history.emplace_back(info.time, verification_value());
    }



    double
    FreeSurfaceScene::verification_value() const
    {
      if (parameters.exact_solution == FlowExactSolution::standing_wave)
        return diagnostics::surface_elevation(solver->phase_field(), parameters.lower_left[0]);
      return diagnostics::front_position(solver->phase_field()) - parameters.lower_left[0];
    }



    double
    FreeSurfaceScene::mean_surface_elevation() const
    {
      const ParsedExpression eta(section + "/Initial water/Surface elevation",
                                 parameters.surface_elevation);
      const unsigned int     n     = 1000;
      const double           width = parameters.upper_right[0] - parameters.lower_left[0];
      double                 sum   = 0.;
      for (unsigned int i = 0; i < n; ++i)
        sum += eta.value(parameters.lower_left[0] + (i + 0.5) * width / n);
      return sum / n - parameters.lower_left[1];
    }



    void
    FreeSurfaceScene::write_output(const unsigned int index, const double time)
    {
      if (scene.test_mode)
        return;
      dealii::TimerOutput::Scope scope(*timer, "fluid: output");
      output.write(*solver, parameters.write_surface, index, time);
    }



    void
    FreeSurfaceScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const double volume = solver->water_volume();
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      statistics.add_value("water_volume", volume);
      statistics.add_value("water_outflow", solver->water_outflow);
      statistics.add_value("volume_drift", balance.drift(volume, solver->water_outflow));
      statistics.add_value("kinetic_energy",
                           diagnostics::kinetic_energy(solver->flow_field(),
                                                       solver->phase_field(),
                                                       parameters.fluid));
      statistics.add_value("max_speed", solver->max_speed());
      statistics.add_value("front", diagnostics::front_position(solver->phase_field()));
      statistics.add_value("flow_iterations", last_report.flow.iterations);
      statistics.add_value("phase_iterations", last_report.phase.iterations);
      statistics.add_value("cells",
                           static_cast<double>(grid->triangulation().n_global_active_cells()));
    }



    bool
    FreeSurfaceScene::finish(const StepInfo &)
    {
      const bool is_writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      double     error     = 0.;
      char       line[400];
      line[0] = '\0';
      if (parameters.exact_solution == FlowExactSolution::hydrostatic)
        {
          const auto errors = diagnostics::hydrostatic_errors(solver->flow_field(), parameters);
          error             = errors[0];
          std::snprintf(line,
                        sizeof(line),
                        "Hydrostatic pressure: largest relative error = %.3e; largest speed "
                        "(spurious currents) = %.3e m/s",
                        errors[0],
                        errors[1]);
        }
      else if (parameters.exact_solution == FlowExactSolution::poiseuille)
        {
          error = diagnostics::poiseuille_error(solver->flow_field(), parameters);
          std::snprintf(line,
                        sizeof(line),
                        "Poiseuille flow: largest nodal error of u_x relative to the peak = "
                        "%.3e",
                        error);
        }
      else if (parameters.exact_solution == FlowExactSolution::martin_moyce)
        {
          const double a = parameters.water_boxes[0].upper[0] - parameters.water_boxes[0].lower[0];
          const auto   c
            = compare_with_martin_moyce(verification_history, a, parameters.fluid.gravity.norm());
          error = c.max_error;
          std::snprintf(line,
                        sizeof(line),
                        "Martin and Moyce: %u points, front x/a largest difference %.3f, "
                        "RMS %.3f; with the time shifted by %.3f, RMS %.3f",
                        c.n_points,
                        c.max_error,
                        c.rms_error,
                        c.best_shift,
                        c.rms_error_shifted);
        }
      else if (parameters.exact_solution == FlowExactSolution::standing_wave)
        {
          const double                           depth = mean_surface_elevation();
          std::vector<std::pair<double, double>> eta;
          for (const auto &[t, y] : verification_history)
            eta.emplace_back(t, y - parameters.lower_left[1]);
          const auto r = analyse_standing_wave(eta,
                                               depth,
                                               parameters.upper_right[0] - parameters.lower_left[0],
                                               parameters.fluid.gravity.norm(),
                                               parameters.fluid.water_viscosity
                                                 / parameters.fluid.water_density);
          // The decay counts where viscosity damps the wave measurably (by more than 5 %
          // over the record); below, the numerical damping would dominate it.
          const bool decays = r.exact_amplitude_ratio < 0.95;
          error             = r.n_crossings < 3 ? 1. :
                              decays ? std::max(std::abs(r.period_error), std::abs(r.decay_error)) :
                                       std::abs(r.period_error);
          std::snprintf(line,
                        sizeof(line),
                        "Standing wave: %u zero crossings, period %.5f s against %.5f s "
                        "(linear theory): relative error %.3e; amplitude after/before %.4f "
                        "against %.4f: decay rate error %.3e%s",
                        r.n_crossings,
                        r.period,
                        r.exact_period,
                        r.period_error,
                        r.amplitude_ratio,
                        r.exact_amplitude_ratio,
                        r.decay_error,
                        decays ? "" : " (not checked: the theory's decay is below 5 %)");
        }
      else if (parameters.exact_solution == FlowExactSolution::darcy)
        {
          error = diagnostics::darcy_error(solver->flow_field(), parameters);
          std::snprintf(line,
                        sizeof(line),
                        "Darcy flow: largest nodal error of u_x relative to rho g kappa / "
                        "(n mu) = %.3e",
                        error);
        }
      else if (parameters.exact_solution == FlowExactSolution::taylor_green)
        {
          error = diagnostics::taylor_green_error(solver->flow_field(), parameters, solver->time);
          std::snprintf(line,
                        sizeof(line),
                        "Taylor-Green vortices: L2 error of the velocity relative to the "
                        "exact field's L2 norm = %.3e",
                        error);
        }
      if (is_writer)
        {
          balance.print_summary(solver->water_outflow);
          output.print_probes();
          // The split of the steps' time (wall times: not in test mode's output).
          if (!scene.test_mode)
            std::printf("Step time: flow assembly %.3g s, preconditioner %.3g s (%llu builds), "
                        "GMRES %.3g s (%llu iterations), phase field %.3g s\n",
                        part_times[0],
                        part_times[1],
                        preconditioner_builds,
                        part_times[2],
                        flow_iterations,
                        part_times[3]);
          if (line[0] != '\0')
            {
              std::printf("%s", line);
              if (parameters.tolerance > 0.)
                std::printf(" <= %g: %s",
                            parameters.tolerance,
                            error <= parameters.tolerance ? "yes" : "no");
              std::printf("\n");
            }
          std::fflush(stdout);
        }
      return !(parameters.tolerance > 0.) || error <= parameters.tolerance;
    }



    std::string
    FreeSurfaceScene::checkpoint_signature() const
    {
      std::ostringstream out;
      out.precision(12);
      out << "free surface flow; grid " << parameters.lower_left << " to " << parameters.upper_right
          << ", cell size " << parameters.cell_size << ", adaptive levels "
          << (parameters.adaptive ? parameters.adaptive_levels : 0) << "; fluids "
          << parameters.fluid.water_density << ' ' << parameters.fluid.air_density;
      // (dynamic subscales are a field of their own in the checkpoint)
      if (parameters.dynamic_subscales)
        out << "; dynamic subscales";
      out << output.signature();
      return out.str();
    }



    std::vector<std::string>
    FreeSurfaceScene::growing_files() const
    {
      return output.growing_files();
    }



    void
    FreeSurfaceScene::save(io::CheckpointRecord &record)
    {
      record.put("fluid/time", solver->time);
      record.put("fluid/last_dt", solver->last_dt);
      record.put("fluid/steps", solver->n_steps);
      balance.save(record);
      record.put("fluid/water_outflow", solver->water_outflow);
      record.put("fluid/last_iterations",
                 std::vector<double>{static_cast<double>(last_report.flow.iterations),
                                     static_cast<double>(last_report.phase.iterations)});
      record.put_files("fluid/field_files", output.files);
      std::vector<double> history;
      for (const auto &[t, x] : verification_history)
        {
          history.push_back(t);
          history.push_back(x);
        }
      record.put("fluid/verification_history", history);
    }



    void
    FreeSurfaceScene::save_data(const std::string &prefix)
    {
      solver->save(prefix);
    }



    void
    FreeSurfaceScene::resume(const io::CheckpointRecord &record,
                             const std::string          &prefix,
                             dealii::TimerOutput        &timer_output)
    {
      timer = &timer_output;
      dealii::TimerOutput::Scope scope(timer_output, "fluid: setup");
      create_solver();
      solver->load(prefix);
      solver->time    = record.get("fluid/time");
      solver->last_dt = record.get("fluid/last_dt");
      solver->n_steps = record.get_unsigned("fluid/steps");
      balance.load(record);
      solver->water_outflow = record.get("fluid/water_outflow");
      const auto &its       = record.get_vector("fluid/last_iterations");
      if (its.size() != 2)
        throw InputError("Checkpoint/Resume",
                         "fluid/last_iterations",
                         "two counts (damaged checkpoint)");
      last_report.flow.iterations  = static_cast<unsigned int>(its[0]);
      last_report.phase.iterations = static_cast<unsigned int>(its[1]);
      output.files                 = record.get_files("fluid/field_files");
      const auto &history          = record.get_vector("fluid/verification_history");
      if (history.size() % 2 != 0)
        throw InputError("Checkpoint/Resume",
                         "fluid/verification_history",
                         "pairs of time and front (damaged checkpoint)");
      verification_history.clear();
      for (std::size_t k = 0; k < history.size(); k += 2)
        verification_history.emplace_back(history[k], history[k + 1]);
      output.open_gauges(true);
    }
  } // namespace fluid
} // namespace slidewave
