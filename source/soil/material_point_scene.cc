#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/core/run_control.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/io/solver_checkpoints.h>
#include <slidewave/soil/hencky_exact_solution.h>
#include <slidewave/soil/material_point_scene.h>
#include <slidewave/soil/particle_properties.h>
#include <sstream>

namespace slidewave
{
  namespace soil
  {
    namespace
    {
      const std::string section = "Material points";
    }



    void
    MaterialPointScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection(section);
      MaterialPointParameters::declare_parameters(prm);
      prm.declare_entry("Check interval",
                        "10",
                        Integer(1),
                        "Every this many steps (and before every output), the material "
                        "points are checked for non-finite values and non-positive volumes, "
                        "for points that left through a side that is not free, and the "
                        "kinetic energy against the energy available (initial "
                        "kinetic + elastic energy + work of gravity); a failed check stops "
                        "the run (exit status 2) with the step, time and point. With "
                        "Physics = granular water the water's guards ('Free surface "
                        "flow/Guards') are checked then too.");
      prm.declare_entry("Output grid",
                        "false",
                        Bool(),
                        "Also write the background grid (grid/*.pvtu, grid.pvd) with the "
                        "nodal mass and velocity of the last step at each output time.");
      prm.enter_subsection("Verification");
      {
        prm.declare_entry("Exact solution",
                          "none",
                          Selection("none|bar vibration|self weight column|rigid rotation|"
                                    "homogeneous deformation"),
                          "'bar vibration': axial vibration of an elastic bar fixed at x = 0 "
                          "and free at x = L, started with v = A sin(pi x / (2 L)); the "
                          "centre-of-mass velocity is compared with A cos(omega t) / (beta L) "
                          "at every step (material of Region 1). 'self weight column': at the "
                          "end, sigma_yy of every point against -rho g (H - Y), Y its initial "
                          "height, normalized by sum rho g H V (Coombs and Augarde 2020). "
                          "'rigid rotation': a body turning rigidly at 'Rotation rate' about "
                          "'Rotation centre' (a prescribed velocity) from the 'uniform' "
                          "initial stress sigma_0: at the end, every point's stress against "
                          "R sigma_0 R^T (R the rotation by omega t; the Jaumann rate turns "
                          "the stress with the material), normalized by |sigma_0|. "
                          "'homogeneous deformation': a stress-free body of a 'hencky drucker "
                          "prager' material (Region 1's) deformed by the constant 'Velocity "
                          "gradient' L (give the same field as 'Prescribed velocity'): at the "
                          "end, every point's stress against the closed-form Hencky stress of "
                          "F = exp(L t) (exact for elastic paths, and for plastic ones with L "
                          "symmetric), normalized by its norm.");
        prm.declare_entry("Bar length", "25", Double(0.), "L of the vibrating bar [m].");
        prm.declare_entry("Bar amplitude",
                          "0.1",
                          Double(0.),
                          "A, the initial velocity amplitude of the bar [m/s].");
        prm.declare_entry("Column height",
                          "1",
                          Double(0.),
                          "H, the initial height of the column's top [m].");
        prm.declare_entry("Rotation rate",
                          "1",
                          Double(),
                          "omega of the rigid rotation [rad/s], counter-clockwise positive.");
        prm.declare_entry("Rotation centre",
                          "0, 0",
                          Anything(),
                          "x, y of the centre of the rigid rotation [m].");
        prm.declare_entry("Velocity gradient",
                          "0, 0, 0, 0",
                          Anything(),
                          "L_xx, L_xy, L_yx, L_yy [1/s] of 'homogeneous deformation' (L_xy = "
                          "dv_x/dy).");
        prm.declare_entry("Tolerance",
                          "0",
                          Double(0.),
                          "If > 0, the run fails (exit status 3) when the error exceeds it "
                          "(bar: largest error over the run, in m/s).");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    MaterialPointScene::MaterialPointScene(const SceneParameters    &scene_parameters,
                                           dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , particle_output(scene_parameters.output_directory)
      , grid_output(scene_parameters.output_directory)
    {
      prm.enter_subsection(section);
      parameters.parse_parameters(prm, section);
      core::check_step_count(scene,
                             parameters.fixed_time_step,
                             section + "/Fixed time step",
                             to_string(parameters.fixed_time_step),
                             "'Fixed time step'");
      write_grid     = prm.get_bool("Output grid");
      check_interval = prm.get_integer("Check interval");
      prm.enter_subsection("Verification");
      {
        const std::string type = prm.get("Exact solution");
        exact_solution         = type == "bar vibration"      ? ExactSolution::bar_vibration :
                                 type == "self weight column" ? ExactSolution::self_weight_column :
                                 type == "rigid rotation"     ? ExactSolution::rigid_rotation :
                                 type == "homogeneous deformation" ?
                                                            ExactSolution::homogeneous_deformation :
                                                            ExactSolution::none;
        rotation_rate          = prm.get_double("Rotation rate");
        {
          const auto centre = parse_number_list(section + "/Verification/Rotation centre",
                                                prm.get("Rotation centre"),
                                                "two numbers x, y",
                                                2);
          rotation_centre   = dealii::Point<2>(centre[0], centre[1]);
        }
        {
          const auto L      = parse_number_list(section + "/Verification/Velocity gradient",
                                           prm.get("Velocity gradient"),
                                           "four numbers L_xx, L_xy, L_yx, L_yy",
                                           4);
          velocity_gradient = dealii::Tensor<2, 2>({{L[0], L[1]}, {L[2], L[3]}});
        }
        if (exact_solution == ExactSolution::homogeneous_deformation
            && (parameters.materials[parameters.regions[0].material_index].model
                  != materials::MaterialModel::hencky_drucker_prager
                || parameters.initial_stress != InitialStress::none))
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "another exact solution: 'homogeneous deformation' needs Region 1 "
                           "of a 'hencky drucker prager' material, stress free at the start "
                           "('Initial stress/Type = none')");
        bar_length    = prm.get_double("Bar length");
        bar_amplitude = prm.get_double("Bar amplitude");
        column_height = prm.get_double("Column height");
        tolerance     = prm.get_double("Tolerance");
      }
      prm.leave_subsection();
      prm.leave_subsection();
    }



    double
    MaterialPointScene::bar_velocity_error(const double time) const
    {
      const auto  &material  = parameters.materials[parameters.regions[0].material_index];
      const double beta      = M_PI / (2. * bar_length);
      const double omega     = beta * std::sqrt(material.youngs_modulus / material.density);
      const auto   integrals = solver->integrals();
      const double exact
        = bar_amplitude * std::cos(omega * (time - scene.start_time)) / (beta * bar_length);
      return std::abs(integrals.momentum_x / integrals.mass - exact);
    }



    double
    MaterialPointScene::column_stress_error() const
    {
      const double g     = std::abs(parameters.gravity[1]);
      double       error = 0., norm = 0.;
      solver->point_cloud().for_each_particle([&](const auto &particle) {
        const auto   p     = particle.get_properties();
        const double rho0  = p[property::mass] / p[property::initial_volume];
        const double exact = -rho0 * g * (column_height - p[property::initial_y]);
        error += std::abs(p[property::stress_yy] - exact) * p[property::initial_volume];
        norm += rho0 * g * column_height * p[property::initial_volume];
      });
      return dealii::Utilities::MPI::sum(error, MPI_COMM_WORLD)
             / dealii::Utilities::MPI::sum(norm, MPI_COMM_WORLD);
    }



    std::array<double, 2>
    MaterialPointScene::rotation_errors(const double time) const
    {
      // sigma(t) = R sigma_0 R^T and x(t) = c + R (X - c), R the rotation by omega t.
      const double               angle = rotation_rate * (time - scene.start_time);
      const double               c = std::cos(angle), s = std::sin(angle);
      const dealii::Tensor<2, 2> R({{c, -s}, {s, c}});
      const auto                &u = parameters.uniform_stress;
      const dealii::Tensor<2, 2> sigma_0({{u[0], u[2]}, {u[2], u[1]}});
      const dealii::Tensor<2, 2> exact  = R * sigma_0 * dealii::transpose(R);
      double                     stress = 0., position = 0.;
      for (const auto &particle : solver->particles())
        {
          const auto                 p = particle.get_properties();
          const dealii::Tensor<2, 2> sigma({{p[property::stress_xx], p[property::stress_xy]},
                                            {p[property::stress_xy], p[property::stress_yy]}});
          stress = std::max(stress, (sigma - exact).norm());
          const dealii::Tensor<1, 2> X({p[property::initial_x] - rotation_centre[0],
                                        p[property::initial_y] - rotation_centre[1]});
          const dealii::Point<2>     x = rotation_centre + R * X;
          position                     = std::max(position, particle.get_location().distance(x));
        }
      return {{dealii::Utilities::MPI::max(stress, MPI_COMM_WORLD) / sigma_0.norm(),
               dealii::Utilities::MPI::max(position, MPI_COMM_WORLD)}};
    }



    std::string
    MaterialPointScene::checkpoint_signature() const
    {
      // What a checkpoint must agree with: the physics, the grid and the materials.
      std::ostringstream out;
      out.precision(12);
      out << "material points; grid " << parameters.lower_left << " to " << parameters.upper_right
          << ", cell size " << parameters.cell_size << ", adaptive levels "
          << (parameters.adaptivity.enabled ? parameters.adaptivity.levels : 0) << "; materials";
      for (const auto &material : parameters.materials)
        out << " " << material.signature();
      out << engine::signature(parameters.velocity_transfer);
      return out.str();
    }



    void
    MaterialPointScene::check_state(const unsigned int step, const double time) const
    {
      const std::string where
        = "at step " + std::to_string(step) + ", t = " + to_string(time) + " s: ";
      const std::string problem = solver->find_invalid_particle();
      if (!problem.empty())
        throw RunFailure(where + problem);

      // Energy must not grow without a source: the kinetic energy can never exceed what
      // was there at the start (kinetic + elastic) plus the work gravity has done since;
      // walls and boundaries do no work, materials and damping only dissipate. 10 % of
      // slack and a floor far below any real motion keep round-off from tripping it.
      const auto   budget    = solver->energy_budget();
      const double available = initial_energy + std::max(0., budget.gravity_work);
      const double floor     = 1e-9 * total_mass
                             * (std::abs(parameters.gravity[1]) + std::abs(parameters.gravity[0]))
                             * parameters.cell_size
                           + 1e-300;
      if (budget.kinetic > 1.1 * available + floor)
        throw RunFailure(where + "the kinetic energy (" + to_string(budget.kinetic)
                         + " J/m) exceeds the energy available to the material (initial "
                           "kinetic and elastic energy plus the work of gravity: "
                         + to_string(available) + " J/m): the run is unstable; fastest: "
                         + solver->describe_fastest_particle()
                         + " (reduce 'Time step multiplier' or use GIMP)");
    }



    void
    MaterialPointScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const auto integrals = solver->integrals();
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      statistics.add_value("particles", integrals.n_particles);
      statistics.add_value("mass", integrals.mass);
      statistics.add_value("lost_mass", integrals.lost_mass);
      statistics.add_value("momentum_x", integrals.momentum_x);
      statistics.add_value("momentum_y", integrals.momentum_y);
      statistics.add_value("kinetic_energy", integrals.kinetic_energy);
      statistics.add_value("max_particle_speed", integrals.max_speed);
      statistics.add_value("runout", integrals.runout);
      statistics.add_value("max_surface_height", integrals.max_height);
      statistics.add_value(
        "cells", static_cast<unsigned int>(solver->triangulation().n_global_active_cells()));
      statistics.add_value("load_imbalance", solver->load_imbalance());
    }



    bool
    MaterialPointScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return RunControl(scene).run(*this, timer);
      });
    }



    core::MemoryEstimate
    MaterialPointScene::memory_estimate() const
    {
      core::MemoryEstimate estimate;
      parameters.add_to_memory_estimate(estimate, section);
      return estimate;
    }



    std::vector<core::OutputFolder>
    MaterialPointScene::output_folders() const
    {
      std::vector<core::OutputFolder> folders{{"particles", "the material points"}};
      if (write_grid)
        folders.push_back({"grid", "the grid ('" + section + "/Output grid')"});
      return folders;
    }



    void
    MaterialPointScene::create_solver(dealii::TimerOutput &timer_output)
    {
      timer  = &timer_output;
      grid   = MaterialPointSolver::make_grid(parameters);
      solver = std::make_unique<MaterialPointSolver>(parameters, *grid);
      solver->set_timer(timer_output);
    }



    void
    MaterialPointScene::set_up(const double start_time, dealii::TimerOutput &timer_output)
    {
      dealii::TimerOutput::Scope scope(timer_output, "mpm: setup");
      create_solver(timer_output);
      solver->setup(start_time);
    }



    void
    MaterialPointScene::check_set_up() const
    {
      if (parameters.fixed_time_step > 0.)
        {
          const double limit = max_time_step_multiplier * solver->stability_limit();
          if (parameters.fixed_time_step > limit)
            throw InputError("Material points/Fixed time step",
                             to_string(parameters.fixed_time_step),
                             "a time step at most the stability limit of this scene, h / "
                             "(sqrt(2) max(c_p + |v_p|)) = "
                               + to_string(limit)
                               + " s (paper 000, Eq. 23 with the largest stable alpha, "
                                 "1/sqrt(2): doc/stability.md)");
        }
    }



    std::string
    MaterialPointScene::description() const
    {
      return "Material points: " + std::to_string(solver->particles().n_global_particles())
             + " particles on " + std::to_string(solver->triangulation().n_global_active_cells())
             + " cells; output in " + scene.output_directory;
    }



    void
    MaterialPointScene::start(const StepInfo &)
    {
      const auto budget = solver->energy_budget();
      initial_energy    = budget.kinetic + budget.elastic;
      total_mass        = solver->integrals().mass;
    }



    double
    MaterialPointScene::stable_time_step()
    {
      dealii::TimerOutput::Scope scope(*timer, "mpm: time step");
      return solver->stable_time_step();
    }



    void
    MaterialPointScene::advance(const StepInfo &info)
    {
      dealii::TimerOutput::Scope scope(*timer, "mpm: advance");
      solver->advance(info.dt);
    }



    double
    MaterialPointScene::homogeneous_deformation_error(const double time) const
    {
      const auto &material = parameters.materials[parameters.regions[0].material_index];
      const auto  exact
        = hencky_homogeneous_state(material, velocity_gradient, time - scene.start_time);
      double error = 0.;
      for (const auto &particle : solver->particles())
        {
          const auto                    p = particle.get_properties();
          dealii::SymmetricTensor<2, 3> sigma;
          sigma[0][0] = p[property::stress_xx];
          sigma[1][1] = p[property::stress_yy];
          sigma[0][1] = p[property::stress_xy];
          sigma[2][2] = p[property::stress_zz];
          error       = std::max(error, (sigma - exact.cauchy_stress).norm());
        }
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          const auto &s = exact.cauchy_stress;
          char        line[240];
          std::snprintf(line,
                        sizeof(line),
                        "Homogeneous deformation: det F = %.6f, %s; exact sigma_xx, sigma_yy, "
                        "sigma_xy, sigma_zz = %.6e, %.6e, %.6e, %.6e Pa",
                        exact.jacobian,
                        exact.plastic ? "plastic" : "elastic",
                        s[0][0],
                        s[1][1],
                        s[0][1],
                        s[2][2]);
          std::cout << line << std::endl;
        }
      return dealii::Utilities::MPI::max(error, MPI_COMM_WORLD) / exact.cauchy_stress.norm();
    }



    void
    MaterialPointScene::after_step(const StepInfo &info)
    {
      // The guards run every 'Check interval' steps and before anything is written, so
      // that no output ever holds a bad state.
      if (info.step % check_interval == 0 || info.reports)
        {
          dealii::TimerOutput::Scope scope(*timer, "mpm: checks");
          check_state(info.step, info.time);
        }
      if (exact_solution == ExactSolution::bar_vibration)
        max_error = std::max(max_error, bar_velocity_error(info.time));
    }



    void
    MaterialPointScene::write_output(const unsigned int index, const double time)
    {
      if (scene.test_mode)
        return;
      dealii::TimerOutput::Scope scope(*timer, "mpm: output");
      if (write_grid)
        {
          // Ghosted copies: the solver's mass vector holds owned entries only.
          using Vector = dealii::LinearAlgebra::distributed::Vector<double>;
          Vector mass(solver->lumped_nodal_mass());
          mass.update_ghost_values();
          std::array<Vector, 2> velocity{{solver->nodal_velocity(0), solver->nodal_velocity(1)}};
          for (auto &v : velocity)
            v.update_ghost_values();
          grid_output.write(solver->dof_handler(),
                            {{"nodal_mass", &mass},
                             {"nodal_velocity_x", &velocity[0]},
                             {"nodal_velocity_y", &velocity[1]}},
                            index,
                            time);
        }
      particle_output.write(solver->particles(), solver->property_layout(), index, time);
    }



    void
    MaterialPointScene::save(io::CheckpointRecord &record)
    {
      io::save_state(record, "mpm", *solver);
      record.put("mpm/max_error", max_error);
      record.put("mpm/initial_energy", initial_energy);
      record.put("mpm/total_mass", total_mass);
      record.put_files("mpm/particle_files", particle_output.files);
      record.put_files("mpm/grid_files", grid_output.files);
    }



    void
    MaterialPointScene::save_data(const std::string &prefix)
    {
      solver->save(prefix);
    }



    void
    MaterialPointScene::resume(const io::CheckpointRecord &record,
                               const std::string          &prefix,
                               dealii::TimerOutput        &timer_output)
    {
      dealii::TimerOutput::Scope scope(timer_output, "mpm: setup");
      max_error             = record.get("mpm/max_error");
      initial_energy        = record.get("mpm/initial_energy");
      total_mass            = record.get("mpm/total_mass");
      particle_output.files = record.get_files("mpm/particle_files");
      grid_output.files     = record.get_files("mpm/grid_files");
      first_step            = record.get_unsigned("run/step");
      create_solver(timer_output);
      solver->load(prefix);
      io::restore_state(record, "mpm", *solver);
    }



    bool
    MaterialPointScene::finish(const StepInfo &info)
    {
      const bool is_writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      dealii::ConditionalOStream pcout(std::cout, is_writer && !scene.test_mode);
      pcout << "Particle relocation: deal.II's full sort in " << solver->n_full_particle_sorts()
            << " of " << info.step - first_step << " steps" << std::endl;
      if (const core::StepTimeline *timeline = solver->step_timeline())
        {
          const auto written = timeline->write(scene.output_directory + "/step_timeline.csv");
          const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
          if (is_writer)
            std::cout << "Step timeline: " << written.rows << " rows (" << timeline->n_steps()
                      << " steps x " << n_ranks << (n_ranks == 1 ? " rank" : " ranks") << "), "
                      << written.complete_rows
                      << " with a time for the scatter and the gather, in step_timeline.csv"
                      << std::endl;
        }

      if (exact_solution == ExactSolution::self_weight_column)
        max_error = column_stress_error();
      if (exact_solution == ExactSolution::rigid_rotation)
        {
          const auto errors = rotation_errors(info.time);
          max_error         = errors[0];
          if (is_writer)
            {
              char line[160];
              std::snprintf(line,
                            sizeof(line),
                            "Rigid rotation by %.4f rad: largest distance of a point from its "
                            "rigidly rotated position = %.3e m",
                            rotation_rate * (info.time - scene.start_time),
                            errors[1]);
              std::cout << line << std::endl;
            }
        }
      if (exact_solution == ExactSolution::homogeneous_deformation)
        max_error = homogeneous_deformation_error(info.time);
      if (exact_solution != ExactSolution::none && is_writer)
        {
          char line[160];
          std::snprintf(line,
                        sizeof(line),
                        "%s error against the exact solution = %.4e",
                        exact_solution == ExactSolution::bar_vibration ?
                          "Largest centre-of-mass velocity" :
                        exact_solution == ExactSolution::rigid_rotation
                            || exact_solution == ExactSolution::homogeneous_deformation ?
                          "Largest normalized stress" :
                          "Normalized sigma_yy",
                        max_error);
          std::cout << line;
          if (tolerance > 0.)
            std::cout << " <= " << tolerance << ": " << (max_error <= tolerance ? "yes" : "no");
          std::cout << std::endl;
        }
      return !(tolerance > 0.) || max_error <= tolerance;
    }
  } // namespace soil
} // namespace slidewave
