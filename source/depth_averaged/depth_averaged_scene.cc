#include <algorithm>
#include <array>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <iostream>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/core/run_control.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/depth_averaged/depth_averaged_scene.h>
#include <slidewave/grid/grid_extent.h>
#include <slidewave/io/solver_checkpoints.h>
#include <slidewave/particles/point_count.h>
#include <slidewave/terrain/earth_bounds.h>
#include <slidewave/terrain/raster_source.h>
#include <sstream>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      const std::string section = "Depth averaged";



      /** Refuses a release (as @p solver has set it up) deeper than the Earth allows
       *  (terrain::largest_release_depth) or whose mass or energy is not finite (issue 29:
       *  depths of 1e300 ran and lost every column in the first step). Collective: every
       *  rank refuses, or none. */
      void
      check_release(const DepthAveragedSolver &solver)
      {
        const auto integrals     = solver.model().integrals(solver.point_cloud());
        const auto [name, value] = solver.release_area().depth_source();
        if (!(integrals.max_depth <= terrain::largest_release_depth))
          throw InputError(section + "/Release/" + name,
                           value,
                           "a release depth h (vertical) of at most "
                             + to_string(terrain::largest_release_depth)
                             + " m at every point of the release area (the deepest column is "
                             + to_string(integrals.max_depth) + " m)");
        const double energy = integrals.kinetic_energy + integrals.potential_energy;
        if (!std::isfinite(energy) || !std::isfinite(integrals.mass))
          throw InputError(section + "/Release/" + name,
                           value,
                           "a release whose mass and energy are finite numbers (mass "
                             + to_string(integrals.mass) + " kg, kinetic energy "
                             + to_string(integrals.kinetic_energy) + " J, potential energy "
                             + to_string(integrals.potential_energy)
                             + " J: check the density, the depth and the initial velocity)");
      }



      /** Subsection "Verification": the exact solutions, the conservation and symmetry
       *  checks and their tolerances. */
      void
      declare_verification_parameters(dealii::ParameterHandler &prm)
      {
        using namespace dealii::Patterns;
        prm.enter_subsection("Verification");
        {
          prm.declare_entry("Exact solution",
                            "none",
                            Selection("none|still state|dam break|sliding block|rigid translation"),
                            "'still state': material at rest with its surface at the "
                            "release's 'Surface' (the lake at rest of paper 001, §4.1): the "
                            "L1 (sum of |e| A_p) and L-infinity errors of h, hu and hv at the "
                            "points in the statistics and at the end (the paper's Table 1). "
                            "'dam break': the dam break along x of 'Left depth' and 'Right "
                            "depth' at 'Dam position' (Ritter for a dry bed, Stoker for a wet "
                            "one): the L1 error of the nodal depth relative to the exact "
                            "volume, sum |h_i - h(x_i, t)| a_i / sum h(x_i, t) a_i, and at "
                            "the end also the columns' own, sum_p |h_p - h(x_p, t)| V_p / h_p "
                            "over the same volume; with a "
                            "'Slope angle', Mangeney et al.'s (2000) dry dam break down the "
                            "plane Z = -x tan(angle) with the Coulomb friction of 'Basal "
                            "friction', compared from the tail of the rarefaction onwards, and "
                            "also the L1 error of the velocity (weighted by the exact depth). "
                            "'sliding block': a slab on the plane Z = -x tan('Slope angle') "
                            "with Coulomb friction: the relative error of its horizontal "
                            "acceleration momentum_x / (M t) against g cos^2 theta "
                            "(tan theta - tan phi). 'rigid translation': every column keeps "
                            "its release depth and moves at its release velocity (a uniform "
                            "layer at the still level of a flat bed, doc/depth-averaged.md): "
                            "the relative L1 error of the columns' depth, "
                            "sum |h_p - h_p0| A_p0 / sum h_p0 A_p0 (h_p0 the release's depth "
                            "where the column started, A_p0 = V_p / h_p0), its largest "
                            "relative value and the largest distance of "
                            "a column from x_p0 + v_p0 t in cell sizes.");
          prm.declare_entry("Slope angle",
                            "0",
                            Double(0., 89.),
                            "theta [degrees] of the plane Z = -x tan(theta) of 'sliding block' "
                            "and of the dam break on a slope (0: Ritter or Stoker).");
          prm.declare_entry("Dam position", "0", Double(), "x0 of the dam break [m].");
          prm.declare_entry("Left depth", "1", Double(0.), "h_l of the dam break [m].");
          prm.declare_entry("Right depth", "0", Double(0.), "h_r of the dam break [m].");
          prm.declare_entry("Conservation check",
                            "false",
                            Bool(),
                            "Add the columns nodal_mass_error and nodal_momentum_error to the "
                            "statistics: the totals of a particle-to-grid transfer against "
                            "the points' (paper 001, Eq. 44), relative to the mass and to "
                            "mass times the largest speed.");
          prm.declare_entry("Conservation tolerance",
                            "0",
                            Double(0.),
                            "With 'Conservation check': if > 0, the run fails (exit status 3) "
                            "when either relative error exceeds it at any statistics row.");
          prm.declare_entry("Symmetry line",
                            "",
                            Anything(),
                            "If a number y_s: the flow must stay symmetric about the line y = "
                            "y_s (a symmetric terrain and release, e.g. paper 001, §4.2). After "
                            "every step, |centroid_y - y_s| / cell size and |momentum_y| / "
                            "(mass x largest speed) are measured; the run fails (exit status 3) "
                            "if the largest exceeds 'Symmetry tolerance'.");
          prm.declare_entry("Symmetry tolerance", "1e-9", Double(0.), "See 'Symmetry line'.");
          prm.declare_entry("Tolerance",
                            "0",
                            Double(0.),
                            "If > 0, the run fails (exit status 3) when the error at the end "
                            "exceeds it (still state: L-infinity of h; dam break: the L1 "
                            "error of the depth; sliding block: the relative error of the "
                            "acceleration; rigid translation: the L1 error of the depth).");
        }
        prm.leave_subsection();
      }
    } // namespace



    void
    DepthAveragedScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.enter_subsection(section);
      DepthAveragedParameters::declare_parameters(prm);
      prm.declare_entry("Check interval",
                        "10",
                        Integer(1),
                        "Every this many steps (and before every output) the columns are "
                        "checked for non-finite values and depths that are not positive, "
                        "for points that crossed a wall, and the kinetic energy against the "
                        "energy released (initial kinetic + potential energy minus the "
                        "potential energy now); a failed check stops the run (exit status "
                        "2) with the step, time and point.");
      prm.declare_entry("Output point table",
                        "false",
                        Bool(),
                        "Also write the columns as a table at each output time, "
                        "points/points_NNNNN.csv (id, x, y, elevation, depth, velocity_x, "
                        "velocity_y, in the order of the columns' identifiers, which do not "
                        "depend on the number of ranks), for the project's scripts.");
      prm.declare_entry("Output grid",
                        "true",
                        Bool(),
                        "Also write the grid (grid/*.pvtu, grid.pvd) with the nodal depth, "
                        "the flow surface h + Z, the terrain and the nodal velocity.");
      prm.enter_subsection("Hazard maps");
      HazardMaps::declare_parameters(prm);
      prm.leave_subsection();
      declare_verification_parameters(prm);
      prm.leave_subsection();
    }



    DepthAveragedScene::DepthAveragedScene(const SceneParameters    &scene_parameters,
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
      if (!parameters.elevation_table.empty())
        parameters.elevation_table = scene.resolve_path(parameters.elevation_table);
      if (!parameters.elevation_raster.empty())
        parameters.elevation_raster = scene.resolve_path(parameters.elevation_raster);
      if (!parameters.release.vector_file.empty())
        parameters.release.vector_file = scene.resolve_path(parameters.release.vector_file);
      if (!parameters.depth_raster.empty())
        parameters.depth_raster = scene.resolve_path(parameters.depth_raster);
      if (parameters.grid_from_raster)
        {
          // Opened (and warped) here once; the solver takes the CRS and the elevations
          // from the same opening.
          parameters.terrain_raster
            = std::make_shared<const terrain::RasterSource>(section + "/Terrain/Raster file",
                                                            parameters.elevation_raster,
                                                            parameters.raster_options);
          const auto footprint = parameters.terrain_raster->footprint();
          // With an adaptive grid, whole coarsest cells (their corners on multiples of
          // them, so also of 'Cell size').
          grid::GridExtent extent;
          extent.cell_size = parameters.cell_size * (1u << parameters.adaptivity.used_levels());
          extent.fit_inside(footprint.lower, footprint.upper, section + "/Grid", "terrain raster");
          parameters.lower_left  = extent.lower_left;
          parameters.upper_right = extent.upper_right;
        }
      write_grid     = prm.get_bool("Output grid");
      write_table    = prm.get_bool("Output point table");
      check_interval = prm.get_integer("Check interval");
      prm.enter_subsection("Hazard maps");
      {
        write_maps    = prm.get_bool("Enable");
        map_threshold = prm.get_double("Thickness threshold");
        map_interval  = prm.get_integer("Interval");
      }
      prm.leave_subsection();
      prm.enter_subsection("Verification");
      {
        const std::string type = prm.get("Exact solution");
        exact_solution         = type == "still state"       ? ExactSolution::still_state :
                                 type == "dam break"         ? ExactSolution::dam_break :
                                 type == "sliding block"     ? ExactSolution::sliding_block :
                                 type == "rigid translation" ? ExactSolution::rigid_translation :
                                                               ExactSolution::none;
        slope_angle            = prm.get_double("Slope angle") * M_PI / 180.;
        dam_position           = prm.get_double("Dam position");
        left_depth             = prm.get_double("Left depth");
        right_depth            = prm.get_double("Right depth");
        check_conservation     = prm.get_bool("Conservation check");
        conservation_tolerance = prm.get_double("Conservation tolerance");
        const std::string line = dealii::Utilities::trim(prm.get("Symmetry line"));
        if (!line.empty())
          symmetry_line = parse_number_list(section + "/Verification/Symmetry line",
                                            line,
                                            "empty or one number y_s",
                                            1)[0];
        symmetry_tolerance = prm.get_double("Symmetry tolerance");
        tolerance          = prm.get_double("Tolerance");
        if (exact_solution == ExactSolution::still_state && parameters.surface.empty())
          throw InputError(section + "/Verification/Exact solution",
                           type,
                           "'still state' only with the release given by its 'Surface' "
                           "(the level the material rests at)");
        if (exact_solution == ExactSolution::dam_break && !(left_depth > 0.))
          throw InputError(section + "/Verification/Left depth",
                           prm.get("Left depth"),
                           "a depth > 0 for 'dam break'");
        const double tan_phi = parameters.friction ? std::tan(parameters.friction_angle) : 0.;
        if ((exact_solution == ExactSolution::sliding_block
             || (exact_solution == ExactSolution::dam_break && slope_angle > 0.))
            && !(std::tan(slope_angle) > tan_phi))
          throw InputError(section + "/Verification/Slope angle",
                           prm.get("Slope angle"),
                           "an angle above the basal friction angle (the exact solutions of "
                           "a slide need tan(theta) > tan(phi))");
        if (exact_solution == ExactSolution::dam_break && slope_angle > 0. && right_depth > 0.)
          throw InputError(section + "/Verification/Right depth",
                           prm.get("Right depth"),
                           "0 for the dam break on a slope (the dry bed of Mangeney et al.)");
      }
      prm.leave_subsection();
      prm.leave_subsection();
      if (exact_solution == ExactSolution::still_state)
        {
          surface = std::make_unique<dealii::FunctionParser<2>>(1);
          surface->initialize("x,y", parameters.surface, {{"pi", M_PI}});
        }
    }



    bool
    DepthAveragedScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer) {
        return RunControl(scene).run(*this, timer);
      });
    }



    core::MemoryEstimate
    DepthAveragedScene::memory_estimate() const
    {
      core::MemoryEstimate estimate;
      const auto          &p      = parameters;
      const auto           points = particles::point_count_bound(
        {p.release}, p.lower_left, p.upper_right, p.cell_size, p.particles_per_direction);
      double cells = particles::grid_cell_count(p.lower_left, p.upper_right, p.cell_size);
      if (p.adaptivity.enabled)
        {
          // The coarsest cells, and at the start the release's cells with the buffer around
          // them, fine, and as many again in the rings of the levels between (an estimate
          // of the start: the fine region follows the flow).
          const double levels = std::pow(4., p.adaptivity.levels);
          const double released
            = static_cast<double>(points) / (p.particles_per_direction * p.particles_per_direction);
          const double side = std::sqrt(released) + 2. * p.adaptivity.buffer_cells;
          cells             = std::min(cells, cells / levels + 2. * side * side);
        }
      estimate.add("grid cells",
                   cells,
                   core::MemoryEstimate::bytes_per_depth_averaged_cell,
                   section + "/Grid/Cell size",
                   to_string(p.cell_size));
      estimate.add("material points",
                   points,
                   core::MemoryEstimate::bytes_per_point,
                   section + "/Release/Particles per direction",
                   std::to_string(p.particles_per_direction));
      if (p.terrain_raster)
        estimate.add("raster pixels",
                     p.terrain_raster->pixel_count(),
                     core::MemoryEstimate::bytes_per_pixel,
                     section + "/Terrain/Raster file",
                     p.elevation_raster);
      return estimate;
    }



    std::vector<core::OutputFolder>
    DepthAveragedScene::output_folders() const
    {
      std::vector<core::OutputFolder> folders{{"particles", "the material points"}};
      if (write_table)
        folders.push_back({"points", "the point tables ('" + section + "/Output point table')"});
      if (write_grid)
        folders.push_back({"grid", "the grid ('" + section + "/Output grid')"});
      if (write_maps)
        folders.push_back({"maps", "the hazard maps ('" + section + "/Hazard maps/Enable')"});
      return folders;
    }



    void
    DepthAveragedScene::create_solver(dealii::TimerOutput &timer_output)
    {
      timer  = &timer_output;
      grid   = DepthAveragedSolver::make_grid(parameters);
      solver = std::make_unique<DepthAveragedSolver>(parameters, *grid);
      // The solver has read what it needs from the terrain raster: no copy of it is kept
      // for the run.
      parameters.terrain_raster.reset();
      solver->set_timer(timer_output);
      if (write_maps)
        maps = std::make_unique<HazardMaps>(parameters, map_threshold);
    }



    void
    DepthAveragedScene::set_up(const double start_time, dealii::TimerOutput &timer_output)
    {
      dealii::TimerOutput::Scope scope(timer_output, "depth averaged: setup");
      create_solver(timer_output);
      solver->setup(start_time);
      if (solver->particles().n_global_particles() == 0)
        {
          const auto [name, value] = solver->release_area().depth_source();
          throw InputError(section + "/Release/" + name,
                           value,
                           "a release with material: the depth is 0 or less at every point of "
                           "the release area");
        }
      check_release(*solver);
    }



    void
    DepthAveragedScene::check_set_up() const
    {
      if (parameters.fixed_time_step > 0.)
        {
          const double limit = 0.70710678118654752 * solver->stability_limit();
          if (parameters.fixed_time_step > limit)
            throw InputError(section + "/Fixed time step",
                             to_string(parameters.fixed_time_step),
                             "a time step at most the stability limit of this scene, h / "
                             "(sqrt(2) max(|v_p| + sqrt(g h_p))) = "
                               + to_string(limit) + " s");
        }
    }



    std::string
    DepthAveragedScene::description() const
    {
      const std::string fitted
        = parameters.grid_from_raster ?
            " (the grid [" + to_string(parameters.lower_left[0]) + ", "
              + to_string(parameters.upper_right[0]) + "] x [" + to_string(parameters.lower_left[1])
              + ", " + to_string(parameters.upper_right[1]) + "], inside the terrain raster)" :
            std::string();
      return "Depth-averaged flow: " + std::to_string(solver->particles().n_global_particles())
             + " columns on " + std::to_string(solver->triangulation().n_global_active_cells())
             + " cells" + fitted + "; output in " + scene.output_directory;
    }



    void
    DepthAveragedScene::start(const StepInfo &)
    {
      const auto integrals = solver->model().integrals(solver->point_cloud());
      initial_energy       = integrals.kinetic_energy + integrals.potential_energy;
      total_mass           = integrals.mass;
      initial_max_depth    = integrals.max_depth;
      release_centre       = dealii::Point<2>(integrals.centroid_x, integrals.centroid_y);
      if (maps)
        maps->record(*solver, scene.start_time);
      if (check_conservation)
        record_conservation();
    }



    double
    DepthAveragedScene::stable_time_step()
    {
      dealii::TimerOutput::Scope scope(*timer, "depth averaged: time step");
      return solver->stable_time_step();
    }



    void
    DepthAveragedScene::advance(const StepInfo &info)
    {
      dealii::TimerOutput::Scope scope(*timer, "depth averaged: advance");
      solver->advance(info.dt);
    }



    void
    DepthAveragedScene::check_state(const unsigned int step, const double time) const
    {
      const std::string where
        = "at step " + std::to_string(step) + ", t = " + to_string(time) + " s: ";
      const std::string problem = solver->model().find_invalid_particle(solver->point_cloud());
      if (!problem.empty())
        throw RunFailure(where + problem);
      // Friction and the Bingham stress only dissipate and walls do no work: the kinetic
      // energy cannot exceed the energy at the start minus the potential energy now (what
      // the descent released; material that left through an open side took its share).
      // 10 % of slack and a floor keep round-off and the potential energy's own error
      // (Z + h / 2 at the points against the discrete forces) out: 1e-4 of the energy
      // scale M g h_max of the release. An unstable run grows past it within steps; the
      // standard hydrostatic form over a terrain step makes about 1e-5 of it.
      const auto   integrals = solver->model().integrals(solver->point_cloud());
      const double released  = initial_energy - integrals.potential_energy;
      const double floor     = 1e-4 * total_mass * parameters.gravity * initial_max_depth;
      if (integrals.lost_mass == 0. && integrals.kinetic_energy > 1.1 * released + floor)
        throw RunFailure(where + "the kinetic energy (" + to_string(integrals.kinetic_energy)
                         + " J) exceeds the energy released (" + to_string(released)
                         + " J): the run is unstable; fastest: "
                         + solver->model().describe_fastest_particle(solver->point_cloud())
                         + " (reduce 'Courant number')");
    }



    void
    DepthAveragedScene::after_step(const StepInfo &info)
    {
      if (info.step % check_interval == 0 || info.reports)
        {
          dealii::TimerOutput::Scope scope(*timer, "depth averaged: checks");
          check_state(info.step, info.time);
        }
      if (maps && (info.step % map_interval == 0 || info.at_end))
        {
          dealii::TimerOutput::Scope scope(*timer, "depth averaged: hazard maps");
          maps->record(*solver, info.time);
        }
      // With a tolerance, the conservation is checked after every step, not only at rows.
      if (check_conservation && (info.reports || conservation_tolerance > 0.))
        record_conservation();
      if (!std::isnan(symmetry_line))
        {
          const auto   integrals = solver->model().integrals(solver->point_cloud());
          const double scale     = integrals.mass * std::max(integrals.max_speed, 1e-300);
          max_asymmetry
            = std::max({max_asymmetry,
                        std::abs(integrals.centroid_y - symmetry_line) / parameters.cell_size,
                        std::abs(integrals.momentum_y) / scale});
        }
    }



    std::string
    DepthAveragedScene::checkpoint_signature() const
    {
      std::ostringstream out;
      out.precision(12);
      out << "depth averaged; grid " << parameters.lower_left << " to " << parameters.upper_right
          << ", cell size " << parameters.cell_size;
      // The coarse cells of an adaptive grid are those of its checkpoint.
      if (parameters.adaptivity.enabled)
        out << ", adaptive levels " << parameters.adaptivity.levels;
      out << "; terrain '" << parameters.elevation << "' at " << parameters.terrain_spacing << " m";
      if (!parameters.elevation_table.empty())
        out << " (table " << parameters.elevation_table << ")";
      if (!parameters.elevation_raster.empty())
        out << " (raster " << parameters.elevation_raster << ")";
      out << "; density " << parameters.density;
      // What a column carries: a checkpoint of another version's columns is refused.
      out << "; " << property::n_properties << " column properties";
      return out.str();
    }



    void
    DepthAveragedScene::save(io::CheckpointRecord &record)
    {
      io::save_state(record, "depth_averaged", *solver);
      record.put("depth_averaged/initial_energy", initial_energy);
      record.put("depth_averaged/total_mass", total_mass);
      record.put("depth_averaged/initial_max_depth", initial_max_depth);
      record.put("depth_averaged/max_conservation_error", max_conservation_error);
      record.put("depth_averaged/max_asymmetry", max_asymmetry);
      record.put("depth_averaged/release_centre",
                 std::vector<double>{release_centre[0], release_centre[1]});
      record.put_files("depth_averaged/particle_files", particle_output.files);
      record.put_files("depth_averaged/grid_files", grid_output.files);
      record.put("depth_averaged/hazard_maps", maps ? 1. : 0.);
    }



    void
    DepthAveragedScene::save_data(const std::string &prefix)
    {
      solver->save(prefix);
      if (maps)
        maps->save(prefix + "_hazard_maps.data");
    }



    void
    DepthAveragedScene::resume(const io::CheckpointRecord &record,
                               const std::string          &prefix,
                               dealii::TimerOutput        &timer_output)
    {
      dealii::TimerOutput::Scope scope(timer_output, "depth averaged: setup");
      initial_energy         = record.get("depth_averaged/initial_energy");
      total_mass             = record.get("depth_averaged/total_mass");
      initial_max_depth      = record.get("depth_averaged/initial_max_depth");
      max_conservation_error = record.get("depth_averaged/max_conservation_error");
      max_asymmetry          = record.get("depth_averaged/max_asymmetry");
      {
        const auto centre = record.get_vector("depth_averaged/release_centre");
        release_centre    = dealii::Point<2>(centre[0], centre[1]);
      }
      particle_output.files = record.get_files("depth_averaged/particle_files");
      grid_output.files     = record.get_files("depth_averaged/grid_files");
      create_solver(timer_output);
      solver->load(prefix);
      io::restore_state(record, "depth_averaged", *solver);
      // The maps go on from the checkpoint's (peaks, arrival times since the start); a
      // checkpoint of a run without maps leaves them to cover the resumed part only.
      if (maps && record.get("depth_averaged/hazard_maps") != 0.)
        maps->load(prefix + "_hazard_maps.data");
      else if (maps && dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cerr << "slidewave: the checkpoint was written without hazard maps: the maps "
                     "cover only the run from t = "
                  << to_string(record.get("run/time")) << " s" << std::endl;
    }
  } // namespace depth_averaged
} // namespace slidewave
