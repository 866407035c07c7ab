#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/depth_averaged/depth_averaged_scene.h>
#include <slidewave/depth_averaged/inclined_plane_solutions.h>
#include <slidewave/water/dam_break_solutions.h>
#include <sstream>

// DepthAveragedScene, what it reports: the conservation and the errors against an exact
// solution (still state, dam break), the statistics, the output files (points, point
// tables, the grid) and, at the end, the hazard maps and the verification verdict
// (finish()). The set-up, the steps, the guards and the checkpoints are in
// depth_averaged_scene.cc.
namespace slidewave
{
  namespace depth_averaged
  {
    void
    DepthAveragedScene::record_conservation()
    {
      conservation           = conservation_errors();
      max_conservation_error = std::max({max_conservation_error, conservation[0], conservation[1]});
    }



    DepthAveragedModel::StillStateErrors
    DepthAveragedScene::still_state_errors() const
    {
      const auto &terrain = solver->model().terrain();
      return solver->model().still_state_errors(solver->point_cloud(),
                                                [&](const dealii::Point<2> &x) {
                                                  return surface->value(x) - terrain.value(x);
                                                });
    }



    std::array<double, 3>
    DepthAveragedScene::dam_break_errors(const double time, const bool with_columns) const
    {
      const water::DamBreakSolution exact(left_depth,
                                          right_depth,
                                          dam_position,
                                          parameters.gravity);
      const InclinedPlaneSolutions  slope(slope_angle,
                                         parameters.friction ? parameters.friction_angle : 0.,
                                         parameters.gravity,
                                         left_depth,
                                         dam_position);
      const bool                    on_slope = slope_angle > 0.;
      // The depth and, on a slope, the mass-weighted velocity the columns give the nodes.
      const auto        state = solver->nodal_state(on_slope);
      const auto       &depth = state.depth;
      const auto        area  = grid->lumped_nodal_area();
      const auto       &dofs  = solver->dof_handler();
      std::vector<bool> done(depth.locally_owned_size(), false);
      // |e_h| a, h a, |e_u| h a, |u| h a.
      double       sums[4] = {0., 0., 0., 0.};
      const double t       = time - scene.start_time;
      // On a slope, the exact solution of an infinite reservoir holds from the tail of the
      // dam's rarefaction on (InclinedPlaneSolutions).
      const double from
        = on_slope ? slope.rarefaction_tail(t) : -std::numeric_limits<double>::max();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto i = cell->vertex_dof_index(v, 0);
              if (!depth.in_local_range(i))
                continue;
              const unsigned int local = depth.get_partitioner()->global_to_local(i);
              if (done[local])
                continue;
              done[local] = true;
              // The node's lumped area: a quarter of each cell around it.
              const dealii::Point<2> &x = cell->vertex(v);
              if (x[0] < from)
                continue;
              const double a = area.local_element(local);
              double       h, u;
              if (on_slope)
                slope.dam_break(x[0], t, h, u);
              else
                exact.evaluate(x[0], t, h, u);
              sums[0] += std::abs(depth[i] - h) * a;
              sums[1] += h * a;
              if (on_slope)
                {
                  sums[2] += std::abs(state.velocity[0][i] - u) * h * a;
                  sums[3] += std::abs(u) * h * a;
                }
            }
      // The columns' own depths at their centres, each over its own area: free of the
      // nodal deposit's quadrature error, which does not shrink with the cell size at a
      // fixed number of columns per cell.
      double columns = 0.;
      if (with_columns)
        solver->point_cloud().for_each_particle([&](const auto &particle) {
          const double x = particle.get_location()[0];
          if (x < from)
            return;
          const auto p = particle.get_properties();
          if (!(p[property::depth] > 0.))
            return; // (the checks stop such a run)
          double h, u;
          if (on_slope)
            slope.dam_break(x, t, h, u);
          else
            exact.evaluate(x, t, h, u);
          columns += std::abs(p[property::depth] - h) * p[property::volume] / p[property::depth];
        });
      double all[5] = {sums[0], sums[1], sums[2], sums[3], columns};
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(all, 5),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(all, 5));
      return {{all[0] / all[1], all[3] > 0. ? all[2] / all[3] : 0., all[4] / all[1]}};
    }



    std::array<double, 2>
    DepthAveragedScene::dry_front(const double time) const
    {
      const double                  threshold = 0.01 * left_depth;
      const double                  t         = time - scene.start_time;
      const water::DamBreakSolution ritter(left_depth, 0., dam_position, parameters.gravity);
      const InclinedPlaneSolutions  slope(slope_angle,
                                         parameters.friction ? parameters.friction_angle : 0.,
                                         parameters.gravity,
                                         left_depth,
                                         dam_position);
      const bool                    on_slope = slope_angle > 0.;
      const auto                    exact    = [&](const double x) {
        double h, u;
        if (on_slope)
          slope.dam_break(x, t, h, u);
        else
          ritter.evaluate(x, t, h, u);
        return h;
      };
      // The exact depth falls to 0 at the tip: bisection between the dam and the tip.
      double below = dam_position,
             above = on_slope ? slope.front(t) :
                                dam_position + 2. * std::sqrt(parameters.gravity * left_depth) * t;
      for (unsigned int k = 0; k < 100 && above - below > 1e-12 * (1. + std::abs(above)); ++k)
        {
          const double middle                         = 0.5 * (below + above);
          (exact(middle) > threshold ? below : above) = middle;
        }
      const auto  depth = solver->nodal_depth();
      const auto &dofs  = solver->dof_handler();
      double      front = -std::numeric_limits<double>::max();
      for (const auto &cell : dofs.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (depth[cell->vertex_dof_index(v, 0)] > threshold)
              front = std::max(front, cell->vertex(v)[0]);
      return {{dealii::Utilities::MPI::max(front, MPI_COMM_WORLD), below}};
    }



    double
    DepthAveragedScene::sliding_block_error(const double time) const
    {
      const double t = time - scene.start_time;
      if (!(t > 0.))
        return 0.;
      const InclinedPlaneSolutions exact(slope_angle,
                                         parameters.friction ? parameters.friction_angle : 0.,
                                         parameters.gravity);
      const auto                   integrals    = solver->model().integrals(solver->point_cloud());
      const double                 acceleration = exact.horizontal_acceleration();
      return std::abs(integrals.momentum_x / (integrals.mass * t) - acceleration) / acceleration;
    }



    DepthAveragedModel::TranslationErrors
    DepthAveragedScene::translation_errors(const double time) const
    {
      const auto &release = solver->release_area();
      return solver->model().translation_errors(
        solver->point_cloud(),
        time - scene.start_time,
        [&release](const dealii::Point<2> &x) { return release.velocity(x); },
        [&release](const dealii::Point<2> &x) {
          // The area the column started in (the first that contains it, as the points
          // were made).
          const auto  &areas = release.regions();
          unsigned int r     = 0;
          while (r + 1 < areas.size() && !areas[r].contains(x))
            ++r;
          return release.depth(x, r);
        });
    }



    std::array<double, 2>
    DepthAveragedScene::conservation_errors() const
    {
      const auto   integrals = solver->model().integrals(solver->point_cloud());
      const auto   nodal     = solver->nodal_totals();
      const double scale     = integrals.mass * std::max(integrals.max_speed, 1e-300);
      return {{std::abs(nodal[0] - integrals.mass) / integrals.mass,
               std::max(std::abs(nodal[1] - integrals.momentum_x),
                        std::abs(nodal[2] - integrals.momentum_y))
                 / scale}};
    }



    void
    DepthAveragedScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const auto integrals = solver->model().integrals(solver->point_cloud());
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      statistics.add_value("particles", integrals.n_particles);
      statistics.add_value("mass", integrals.mass);
      statistics.add_value("lost_mass", integrals.lost_mass);
      statistics.add_value("momentum_x", integrals.momentum_x);
      statistics.add_value("momentum_y", integrals.momentum_y);
      statistics.add_value("kinetic_energy", integrals.kinetic_energy);
      statistics.add_value("potential_energy", integrals.potential_energy);
      statistics.add_value("max_speed", integrals.max_speed);
      statistics.add_value("max_depth", integrals.max_depth);
      statistics.add_value("max_travel", integrals.max_travel);
      statistics.add_value("x_min", integrals.x_min);
      statistics.add_value("x_max", integrals.x_max);
      statistics.add_value("y_min", integrals.y_min);
      statistics.add_value("y_max", integrals.y_max);
      statistics.add_value("centroid_x", integrals.centroid_x);
      statistics.add_value("centroid_y", integrals.centroid_y);
      statistics.add_value("covered_area", integrals.covered_area);
      statistics.add_value("load_imbalance", solver->load_imbalance());
      if (check_conservation)
        {
          statistics.add_value("nodal_mass_error", conservation[0]);
          statistics.add_value("nodal_momentum_error", conservation[1]);
        }
      if (exact_solution == ExactSolution::still_state)
        {
          const auto        errors  = still_state_errors();
          const std::string names[] = {"h", "hu", "hv"};
          for (unsigned int i = 0; i < 3; ++i)
            {
              statistics.add_value("error_" + names[i] + "_l1", errors.l1[i]);
              statistics.add_value("error_" + names[i] + "_linf", errors.linf[i]);
            }
        }
      if (exact_solution == ExactSolution::dam_break)
        {
          const auto errors = dam_break_errors(info.time);
          statistics.add_value("depth_error_l1", errors[0]);
          if (slope_angle > 0.)
            statistics.add_value("velocity_error_l1", errors[1]);
        }
      if (exact_solution == ExactSolution::sliding_block)
        statistics.add_value("acceleration_error", sliding_block_error(info.time));
      if (exact_solution == ExactSolution::rigid_translation)
        {
          const auto errors = translation_errors(info.time);
          statistics.add_value("depth_error_l1", errors.depth_l1);
          statistics.add_value("depth_error_max", errors.depth_max);
          statistics.add_value("position_error", errors.position_max / parameters.cell_size);
        }
    }



    void
    DepthAveragedScene::write_output(const unsigned int index, const double time)
    {
      if (scene.test_mode)
        return;
      dealii::TimerOutput::Scope scope(*timer, "depth averaged: output");
      solver->model().refresh_effective_stress(solver->point_cloud());
      particle_output.write(solver->particles(), solver->model().layout(), index, time);
      if (write_table)
        write_point_table(index);
      if (write_grid)
        {
          using Vector         = dealii::LinearAlgebra::distributed::Vector<double>;
          const Vector depth   = solver->nodal_depth();
          const Vector terrain = solver->nodal_elevation();
          Vector       level(depth);
          level += terrain;
          grid_output.write(solver->dof_handler(),
                            {{"depth", &depth},
                             {"surface", &level},
                             {"elevation", &terrain},
                             {"velocity_x", &solver->nodal_velocity(0)},
                             {"velocity_y", &solver->nodal_velocity(1)}},
                            index,
                            time);
        }
    }



    void
    DepthAveragedScene::write_point_table(const unsigned int index) const
    {
      // Each rank's rows, gathered on rank 0, which writes them in the order of the
      // columns' identifiers (the same file on any number of ranks).
      constexpr unsigned int n_columns = 7;
      std::vector<double>    rows;
      rows.reserve(n_columns * solver->particles().n_locally_owned_particles());
      const auto &terrain = solver->model().terrain();
      for (const auto &particle : solver->particles())
        {
          const auto              p = particle.get_properties();
          const dealii::Point<2> &x = particle.get_location();
          rows.insert(rows.end(),
                      {static_cast<double>(particle.get_id()),
                       x[0],
                       x[1],
                       terrain.value(x),
                       p[property::depth],
                       p[property::velocity_x],
                       p[property::velocity_y]});
        }
      const auto all = dealii::Utilities::MPI::gather(MPI_COMM_WORLD, rows, 0);
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      std::vector<const double *> sorted;
      for (const auto &part : all)
        for (std::size_t r = 0; r < part.size(); r += n_columns)
          sorted.push_back(part.data() + r);
      std::sort(sorted.begin(), sorted.end(), [](const double *a, const double *b) {
        return a[0] < b[0];
      });
      char name[32];
      std::snprintf(name, sizeof(name), "points_%05u.csv", index);
      std::ofstream file(scene.output_directory + "/points/" + name);
      file.precision(9);
      file << "id,x,y,elevation,depth,velocity_x,velocity_y\n";
      for (const double *row : sorted)
        {
          file << static_cast<dealii::types::particle_index>(row[0]);
          for (unsigned int c = 1; c < n_columns; ++c)
            file << ',' << row[c];
          file << '\n';
        }
      file.close();
      require_written(file, scene.output_directory + "/points/" + name);
    }



    bool
    DepthAveragedScene::finish(const StepInfo &info)
    {
      const bool is_writer = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (maps)
        {
          const std::string summary = maps->write(scene.output_directory + "/maps",
                                                  *solver,
                                                  solver->crs(),
                                                  release_centre,
                                                  scene.start_time);
          if (is_writer && !scene.test_mode)
            std::printf("Hazard maps in %s/maps\n", scene.output_directory.c_str());
          // The test mode echoes the summary (the maps' files are compared elsewhere).
          if (is_writer && scene.test_mode)
            std::printf("Hazard maps: %s\n", summary.c_str());
        }
      if (parameters.adaptivity.enabled && scene.test_mode)
        {
          // The grid that followed the flow: its cells now and how often it changed.
          const auto cells = solver->triangulation().n_global_active_cells();
          if (is_writer)
            std::printf("Adaptive grid: %llu cells at the end, %u changes\n",
                        static_cast<unsigned long long>(cells),
                        grid->n_changes());
        }
      if (exact_solution == ExactSolution::still_state)
        {
          const auto errors = still_state_errors();
          max_error         = errors.linf[0];
          if (is_writer)
            {
              std::printf("Still state at t = %g s (paper 001, Table 1):\n", info.time);
              std::printf("  variable  L1          L-infinity\n");
              const char *names[] = {"h", "hu", "hv"};
              for (unsigned int i = 0; i < 3; ++i)
                std::printf("  %-8s  %.3e   %.3e\n", names[i], errors.l1[i], errors.linf[i]);
            }
        }
      const double t = info.time - scene.start_time;
      if (exact_solution == ExactSolution::dam_break && slope_angle > 0.)
        {
          const auto   errors    = dam_break_errors(info.time, true);
          const auto   integrals = solver->model().integrals(solver->point_cloud());
          const double front
            = InclinedPlaneSolutions(slope_angle,
                                     parameters.friction ? parameters.friction_angle : 0.,
                                     parameters.gravity,
                                     left_depth,
                                     dam_position)
                .front(t);
          max_error = errors[0];
          if (is_writer)
            std::printf("Dam break on a %g deg slope (Mangeney et al. 2000) at t = %g s: "
                        "relative L1 error of the depth = %.4e (the columns' own "
                        "depths: %.4e), of the velocity = %.4e; front x = %.4f m (the farthest "
                        "column), exact %.4f m, error %.4f m "
                        "of %.4f m travelled\n",
                        slope_angle * 180. / M_PI,
                        t,
                        errors[0],
                        errors[2],
                        errors[1],
                        integrals.x_max,
                        front,
                        integrals.x_max - front,
                        front - dam_position);
        }
      else if (exact_solution == ExactSolution::dam_break)
        {
          const auto errors = dam_break_errors(info.time, true);
          max_error         = errors[0];
          if (is_writer)
            std::printf("Dam break (%s) at t = %g s: relative L1 error of the depth = %.4e "
                        "(the columns' own depths: %.4e)\n",
                        right_depth > 0. ? "Stoker" : "Ritter",
                        t,
                        errors[0],
                        errors[2]);
        }
      if (exact_solution == ExactSolution::dam_break && !(right_depth > 0.))
        {
          const auto front = dry_front(info.time);
          if (is_writer)
            std::printf("Front (the last node deeper than 1 %% of the left depth) x = %.4f m, "
                        "exact %.4f m: error %.4f m, %.2f %% of the %.4f m travelled\n",
                        front[0],
                        front[1],
                        front[0] - front[1],
                        100. * (front[0] - front[1]) / (front[1] - dam_position),
                        front[1] - dam_position);
        }
      if (exact_solution == ExactSolution::sliding_block)
        {
          const auto   integrals = solver->model().integrals(solver->point_cloud());
          const double exact
            = InclinedPlaneSolutions(slope_angle,
                                     parameters.friction ? parameters.friction_angle : 0.,
                                     parameters.gravity)
                .horizontal_acceleration();
          max_error = sliding_block_error(info.time);
          if (is_writer)
            std::printf("Sliding block on a %g deg slope at t = %g s: horizontal acceleration "
                        "momentum_x / (M t) = %.9f m/s^2, exact g cos^2 theta (tan theta - "
                        "tan phi) = %.9f m/s^2, relative error %.3e\n",
                        slope_angle * 180. / M_PI,
                        t,
                        integrals.momentum_x / (integrals.mass * t),
                        exact,
                        max_error);
        }
      if (exact_solution == ExactSolution::rigid_translation)
        {
          const auto errors = translation_errors(info.time);
          max_error         = errors.depth_l1;
          if (is_writer)
            std::printf("Rigid translation at t = %g s: relative L1 error of the columns' "
                        "depth = %.4e (largest %.4e of the depth); largest distance from "
                        "x_p0 + v_p0 t = %.4e cell sizes\n",
                        t,
                        errors.depth_l1,
                        errors.depth_max,
                        errors.position_max / parameters.cell_size);
        }
      bool conserved = true;
      if (check_conservation && conservation_tolerance > 0.)
        {
          conserved = max_conservation_error <= conservation_tolerance;
          if (is_writer)
            std::printf("Largest relative difference of the nodal totals from the points' "
                        "(mass, momentum) %s %g: %s\n",
                        conserved ? "<=" : ">",
                        conservation_tolerance,
                        conserved ? "yes" : "no");
        }
      if (!std::isnan(symmetry_line))
        {
          const bool symmetric = max_asymmetry <= symmetry_tolerance;
          conserved            = conserved && symmetric;
          if (is_writer)
            std::printf("Largest asymmetry about y = %g (centroid offset / cell size, "
                        "momentum_y / (mass x speed)) %s %g: %s\n",
                        symmetry_line,
                        symmetric ? "<=" : ">",
                        symmetry_tolerance,
                        symmetric ? "yes" : "no");
        }
      if (exact_solution != ExactSolution::none && tolerance > 0. && is_writer)
        std::printf("Error %.4e <= %g: %s\n",
                    max_error,
                    tolerance,
                    max_error <= tolerance ? "yes" : "no");
      std::fflush(stdout);
      return conserved && (!(tolerance > 0.) || max_error <= tolerance);
    }
  } // namespace depth_averaged
} // namespace slidewave
