#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deal.II/base/mpi.h>
#include <limits>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/core/run_control.h>
#include <slidewave/core/timed_run.h>
#include <slidewave/fluid/velocity_subscales.h>
#include <slidewave/granular/granular_water_scene.h>
#include <slidewave/grid/load_balancing_parameters.h>
#include <slidewave/soil/particle_properties.h>
#include <stdexcept>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** The partitioning weight of a degree of freedom of the water and of the phase
       *  field in this physics: that of a point at the default 'Material points/Load
       *  balancing/Particle weight' (create_solvers() says why). */
      constexpr unsigned int water_dof_weight
        = grid::LoadBalancingParameters::default_particle_weight;
    } // namespace



    void
    GranularWaterScene::declare_parameters(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection(section);
      GranularWaterParameters::declare_parameters(prm);
      prm.leave_subsection();
    }



    GranularWaterScene::GranularWaterScene(const SceneParameters    &scene_parameters,
                                           dealii::ParameterHandler &prm)
      : scene(scene_parameters)
      , particle_output(scene_parameters.output_directory)
      , fluid_output(scene_parameters.output_directory, {})
      , verification(scene_parameters, soil_parameters, fluid_parameters, parameters)
    {
      prm.enter_subsection(section);
      parameters.parse_parameters(prm, section);
      prm.leave_subsection();
      prm.enter_subsection(soil_section);
      soil_parameters.parse_parameters(prm, soil_section);
      check_interval = prm.get_integer("Check interval");
      prm.leave_subsection();
      prm.enter_subsection(fluid_section);
      fluid_parameters.parse_parameters(prm);
      prm.leave_subsection();
      soil_parameters.point_forces = parameters.top_load > 0.;
      // The skeleton's rigid solids hold the water too.
      fluid_parameters.solids = soil_parameters.solids;
      fluid_output            = fluid::FreeSurfaceOutput(scene.output_directory,
                                              fluid_parameters.gauges,
                                              fluid_parameters.pressure_probes);

      check_parameters();
    }



    bool
    GranularWaterScene::run()
    {
      return run_with_timer(scene.test_mode, [this](dealii::TimerOutput &timer_output) {
        return RunControl(scene).run(*this, timer_output);
      });
    }



    core::MemoryEstimate
    GranularWaterScene::memory_estimate() const
    {
      core::MemoryEstimate estimate;
      soil_parameters.add_to_memory_estimate(estimate, soil_section);
      const double nx
        = std::round((fluid_parameters.upper_right[0] - fluid_parameters.lower_left[0])
                     / fluid_parameters.cell_size),
        ny = std::round((fluid_parameters.upper_right[1] - fluid_parameters.lower_left[1])
                        / fluid_parameters.cell_size);
      // Flow (Q1^2-Q1), phase field and the skeleton's fields (fluid fraction, inverse
      // permeability, flux; semi-implicit: the flux of the step's start too): eight or ten
      // unknowns per node; the semi-implicit coupling's projection (DragProjection) seven
      // vectors per node and a 4 x 4 matrix per cell, about 25 per node at most.
      estimate.add("water unknowns",
                   (parameters.implicit_drag ? (parameters.projected_drag  ? 35. :
                                                parameters.consistent_drag ? 45. :
                                                                             10.) :
                                               8.)
                     * (nx + 1.) * (ny + 1.),
                   core::MemoryEstimate::bytes_per_dof,
                   fluid_section + "/Grid/Cell size",
                   to_string(fluid_parameters.cell_size));
      fluid::VelocitySubscales::add_to_memory_estimate(estimate,
                                                       fluid_parameters,
                                                       fluid_section,
                                                       nx * ny);
      return estimate;
    }



    std::vector<core::OutputFolder>
    GranularWaterScene::output_folders() const
    {
      return {{"particles", "the skeleton's points"}, {"free_surface", "the water's fields"}};
    }



    void
    GranularWaterScene::create_solvers()
    {
      grid         = fluid::FreeSurfaceSolver::make_grid(fluid_parameters);
      fluid_solver = std::make_unique<fluid::FreeSurfaceSolver>(fluid_parameters, *grid);
      // Semi-implicit drag: the water eliminates the skeleton's momentum (PorousMedium).
      fluid_solver->enable_moving_solid(parameters.implicit_drag ? parameters.grain_density : 0.,
                                        parameters.consistent_drag ? &nodal_grains : nullptr);
      // The grid's partition among the ranks: the water's step is most of the work and
      // runs on every cell, so a degree of freedom of the water or the phase field weighs
      // as much as a point at the default 'Particle weight' (16 per cell: a cell of water
      // weighs as much as 16 points, a cell with 4 x 4 points twice as much). The dry
      // points' default alone (a point against a cell's 1000, the water's 100 per degree of
      // freedom) gave one rank nearly all of the water, and two ranks were slower than one
      // (doc/granular-water.md, "Partition").
      fluid_solver->set_partition_weight_per_dof(water_dof_weight);
      model = std::make_unique<PorousSkeletonModel>(soil_parameters,
                                                    parameters,
                                                    fluid_parameters.fluid.water_density,
                                                    fluid_parameters.fluid.water_viscosity);
      Engine::Settings settings;
      settings.shape_function            = soil_parameters.shape_function;
      settings.flip_fraction             = soil_parameters.flip_fraction;
      settings.velocity_transfer         = soil_parameters.velocity_transfer;
      settings.flip_reference_multiplier = soil::reference_time_step_multiplier;
      settings.musl                      = soil_parameters.update_scheme != soil::UpdateScheme::usl;
      settings.full_sort_every_step      = soil_parameters.full_sort_every_step;
      settings.particle_weight           = soil_parameters.adaptivity.particle_weight;
      settings.timer_name                = "granular: skeleton";
      engine                             = std::make_unique<Engine>(*grid,
                                        *model,
                                        soil_parameters.boundaries,
                                        soil_parameters.walls,
                                        soil_parameters.solids,
                                        settings);
      exchange = std::make_unique<SkeletonFluidExchange>(*grid, fluid_parameters);
      if (parameters.projected_drag)
        projection
          = std::make_unique<DragProjection>(*grid, fluid_parameters, parameters.grain_density);
    }



    void
    GranularWaterScene::set_up(const double start_time, dealii::TimerOutput &timer_output)
    {
      timer = &timer_output;
      dealii::TimerOutput::Scope scope(timer_output, "granular: setup");
      create_solvers();
      // The points create the grid (partitioned by the points to come), then the water.
      engine->create_points(start_time,
                            soil_parameters.regions,
                            soil_parameters.particles_per_direction,
                            [this](std::vector<double>    &properties,
                                   const dealii::Point<2> &position,
                                   const unsigned int      region_index,
                                   const double            hx,
                                   const double            hy) {
                              // No grains inside a rigid solid.
                              if (grid::inside_a_solid(fluid_parameters.solids, position))
                                return false;
                              model->fill_new_point(properties, position, region_index, hx, hy);
                              return true;
                            });
      // The water at rest on its hydrostatic pressure, the grains on their effective
      // weight: a saturated layer in equilibrium from the start.
      fluid_solver->start_hydrostatic();
      fluid_solver->initialize(start_time);
      // On an adaptive grid the points made the cells they fill fine; the water's initial
      // surface then does the same, its state set again on the finer cells.
      for (unsigned int l = 0; l < grid->adaptive_levels(); ++l)
        {
          if (!grid->adapt())
            break;
          fluid_solver->initialize(start_time);
        }
      if (soil_parameters.initial_stress == soil::InitialStress::uniform)
        model->set_uniform_stress(engine->point_cloud());
      else if (soil_parameters.initial_stress == soil::InitialStress::geostatic)
        model->set_geostatic_stress(engine->point_cloud(), [this](const dealii::Point<2> &x) {
          return fluid_solver->initial_density(x) / parameters.grain_density;
        });
      if (parameters.top_load > 0.)
        apply_top_load();
      // The water sees the grains from the start: the first row's water volume is the
      // integral of n phi, as every later row's (each step hands the skeleton over anew,
      // with the walls and solids updated to its time first: this hand-over's solid flux,
      // held at every wall and solid, is read by nothing before the first step's).
      engine->scatter_points();
      exchange->to_fluid(engine->nodal_workspace(),
                         engine->velocity_constraints(),
                         model->empty_node_mass(),
                         skeleton_fields(),
                         0.,
                         nullptr);
      balance.start(fluid_solver->water_volume());
      verification.check_points(engine->point_cloud());
      verification.open_files(false);
      fluid_output.open_gauges(false);
    }



    void
    GranularWaterScene::apply_top_load()
    {
      double top = -std::numeric_limits<double>::max();
      for (const auto &particle : engine->point_cloud().particles())
        top = std::max(top, particle.get_location()[1]);
      top = dealii::Utilities::MPI::max(top, MPI_COMM_WORLD);
      // The top row: within half a point spacing of the highest point.
      const double row  = 0.5 * soil_parameters.cell_size / soil_parameters.particles_per_direction;
      const double load = parameters.top_load;
      model->set_point_forces(engine->point_cloud(),
                              [&](const dealii::Particles::ParticleAccessor<2> &particle) {
                                dealii::Tensor<1, 2> force;
                                if (particle.get_location()[1] > top - row)
                                  force[1]
                                    = -load * 2.
                                      * particle.get_properties()[soil::property::domain_half_x];
                                return force;
                              });
    }



    void
    GranularWaterScene::check_set_up() const
    {
      // (With sub-cycling the skeleton's sub-steps keep within its P-wave limit.)
      const double limit = soil::max_time_step_multiplier
                           * (parameters.sub_cycling ? coupling_limit() : stability_limit());
      if (soil_parameters.fixed_time_step > limit)
        throw InputError(soil_section + "/Fixed time step",
                         to_string(soil_parameters.fixed_time_step),
                         "a time step at most the stability limit of this scene, "
                           + std::string(parameters.implicit_drag ?
                                           "h / max(c_p + |v_p|) / sqrt(2) = " :
                                           "min(h / max(c_p + |v_p|), rho^s (1 - n) k / mu) / "
                                           "sqrt(2) = ")
                           + to_string(limit) + " s (the skeleton's Courant limit"
                           + (parameters.implicit_drag ? "" : " and the explicit coupling's")
                           + ", doc/granular-water.md)");
      core::check_step_count(scene,
                             step_limit(),
                             fluid_section + "/Time stepping/Maximum time step",
                             to_string(fluid_parameters.maximum_time_step),
                             "the first step");
    }



    std::string
    GranularWaterScene::description() const
    {
      return "Granular water: " + std::to_string(grid->triangulation().n_global_active_cells())
             + " cells, " + std::to_string(engine->point_cloud().particles().n_global_particles())
             + " skeleton points, "
             + std::to_string(fluid_solver->flow_field().dof_handler().n_dofs())
             + " flow unknowns; output in " + scene.output_directory;
    }



    double
    GranularWaterScene::stable_time_step()
    {
      return step_limit();
    }



    SkeletonFields
    GranularWaterScene::skeleton_fields()
    {
      return SkeletonFields{&fluid_solver->solid_fraction_field(),
                            &fluid_solver->inverse_permeability_field(),
                            &fluid_solver->solid_flux_field(),
                            fluid_solver->start_flux_field()};
    }



    double
    GranularWaterScene::skeleton_limit() const
    {
      // The skeleton's P-wave crossing a cell (Eq. 23 with alpha = 1).
      return engine->stability_limit();
    }



    double
    GranularWaterScene::coupling_limit() const
    {
      // The explicit coupling's time scale rho^s (1 - n) k / mu (measured: the Terzaghi
      // column blows up at 0.9 of it, doc/granular-water.md); none when semi-implicit.
      return parameters.implicit_drag ? std::numeric_limits<double>::infinity() :
                                        model->coupling_time_scale(engine->point_cloud());
    }



    double
    GranularWaterScene::stability_limit() const
    {
      return std::min(skeleton_limit(), coupling_limit());
    }



    double
    GranularWaterScene::step_limit() const
    {
      if (soil_parameters.fixed_time_step > 0.)
        return soil_parameters.fixed_time_step;
      // With sub-cycling the water's step need not wait for the skeleton's P-wave.
      const double limit = parameters.sub_cycling ? coupling_limit() : stability_limit();
      return std::min(fluid_solver->stable_time_step(),
                      soil_parameters.time_step_multiplier * limit);
    }



    void
    GranularWaterScene::advance(const StepInfo &info)
    {
      // The skeleton's sub-steps within the water's step (one without sub-cycling).
      const unsigned int n_sub
        = parameters.sub_cycling ? static_cast<unsigned int>(std::ceil(
            info.dt / (soil_parameters.time_step_multiplier * skeleton_limit()) - 1e-12)) :
                                   1;
      n_substeps                         = std::max(n_sub, 1u);
      const double                dt     = info.dt / n_substeps;
      const grid::NodalWorkspace &nodes  = engine->nodal_workspace();
      const SkeletonFields        fields = skeleton_fields();
      for (unsigned int k = 0; k < n_substeps; ++k)
        {
          {
            dealii::TimerOutput::Scope scope(*timer, "granular: skeleton to grid");
            engine->begin_step();
          }
          {
            // The skeleton's fields now: the water's step reads them (first sub-step), the
            // water's force on the grains the skeleton's velocity in the drag (each).
            dealii::TimerOutput::Scope scope(*timer, "granular: exchange");
            // (the phase field reads the flux of the step's start at the water's step only)
            SkeletonFields sub_step_fields = fields;
            if (k > 0)
              sub_step_fields.start_flux = nullptr;
            exchange->to_fluid(nodes,
                               engine->velocity_constraints(),
                               model->empty_node_mass(),
                               sub_step_fields,
                               parameters.implicit_drag && k == 0 ? info.dt : 0.,
                               &fluid_solver->flow_field());
          }
          if (k == 0)
            {
              if (parameters.consistent_drag)
                prepare_nodal_grains();
              dealii::TimerOutput::Scope scope(*timer, "granular: water");
              last_report = fluid_solver->advance(info.dt);
            }
          {
            dealii::TimerOutput::Scope scope(*timer, "granular: exchange");
            if (water_force[0].get_partitioner() != nodes.nodal_mass.get_partitioner())
              {
                for (auto *f : {&water_force[0], &water_force[1]})
                  f->reinit(nodes.nodal_mass);
                if (!projection && !parameters.consistent_drag) // the lumped drag's W_I
                  water_drag.reinit(nodes.nodal_mass);
              }
            if (projection || parameters.consistent_drag)
              project_water_force(fields, dt);
            else
              exchange->to_skeleton(fluid_solver->flow_field(),
                                    fluid_solver->phase_field(),
                                    fields,
                                    nodes,
                                    water_force,
                                    parameters.implicit_drag ? &water_drag : nullptr);
            engine->add_nodal_forces(water_force);
            if (parameters.implicit_drag && !projection && !parameters.consistent_drag)
              {
                // The owned nodes of this step's points (the others stay as the scatter
                // leaves them).
                auto              &field   = engine->model_field(PorousSkeletonModel::water_drag);
                const unsigned int n_owned = nodes.nodal_mass.locally_owned_size();
                for (const unsigned int i : nodes.active())
                  if (i < n_owned)
                    field.local_element(i) = water_drag.local_element(i);
              }
            if (parameters.forchheimer)
              exchange->relative_speed(fluid_solver->flow_field(),
                                       fields,
                                       nodes,
                                       engine->model_field(PorousSkeletonModel::relative_speed));
          }
          dealii::TimerOutput::Scope scope(*timer, "granular: skeleton update");
          engine->finish_step(dt);
          if (parameters.forchheimer)
            engine->model_field(PorousSkeletonModel::relative_speed).zero_out_ghost_values();
        }
    }



    void
    GranularWaterScene::project_water_force(const SkeletonFields &fields, const double dt)
    {
      // The grains' velocity of the new step is v* + dv (DragProjection, or the water's
      // solve: fluid::NodalGrainsCoupling): the force that takes the grid update from
      // momentum / m there is the old pressure's, which v* holds
      // (SkeletonFluidExchange::to_fluid), and m dv / dt.
      const grid::NodalWorkspace &nodes = engine->nodal_workspace();
      if (projection)
        projection->increment(fluid_solver->flow_field(),
                              fluid_solver->phase_field(),
                              fields,
                              nodes,
                              engine->velocity_constraints(),
                              dt,
                              water_force);
      const fluid::NodalGrainsCoupling *coupling = fluid_solver->nodal_grains_coupling();
      if (!projection && coupling == nullptr)
        throw std::logic_error("GranularWaterScene: no grains' nodal coupling");
      const auto        &pressure = exchange->predictor_pressure_force();
      const unsigned int n_owned  = nodes.nodal_mass.locally_owned_size();
      for (unsigned int d = 0; d < 2; ++d)
        {
          const auto &increment = projection ? water_force[d] : coupling->increment().block(d);
          for (unsigned int i = 0; i < n_owned; ++i)
            water_force[d].local_element(i)
              = pressure[d].local_element(i)
                + nodes.nodal_mass.local_element(i) * increment.local_element(i) / dt;
          water_force[d].zero_out_ghost_values();
        }
    }



    void
    GranularWaterScene::prepare_nodal_grains()
    {
      const grid::NodalWorkspace &nodes = engine->nodal_workspace();
      if (grains_free[0].get_partitioner() != nodes.nodal_mass.get_partitioner())
        for (auto *f : {&grains_free[0], &grains_free[1]})
          f->reinit(nodes.nodal_mass);
      const unsigned int n_owned = nodes.nodal_mass.locally_owned_size();
      const double       empty   = model->empty_node_mass();
      for (unsigned int i = 0; i < n_owned; ++i)
        grains_free[0].local_element(i) = grains_free[1].local_element(i)
          = nodes.nodal_mass.local_element(i) > empty ? 1. : 0.;
      engine->velocity_constraints().apply(grains_free[0], grains_free[1]);
      for (const unsigned int i : nodes.hanging_nodes())
        if (i < n_owned)
          grains_free[0].local_element(i) = grains_free[1].local_element(i) = 0.;
      nodal_grains.nodes = &nodes;
      nodal_grains.free  = {{&grains_free[0], &grains_free[1]}};
    }



    void
    GranularWaterScene::write_output(const unsigned int index, const double time)
    {
      if (scene.test_mode)
        return;
      dealii::TimerOutput::Scope scope(*timer, "granular: output");
      particle_output.write(engine->point_cloud().particles(), model->layout(), index, time);
      fluid_output.write(*fluid_solver, fluid_parameters.write_surface, index, time);
    }



    void
    GranularWaterScene::add_statistics(Statistics &statistics, const StepInfo &info) const
    {
      const auto skeleton = model->integrals(engine->point_cloud());
      statistics.add_value("time", info.time);
      statistics.add_value("step", info.step);
      statistics.add_value("dt", info.dt);
      // The balance, (water_volume + water_outflow - the first row's water_volume) / that
      // volume (WaterBalance::drift): its cancellation usually shows the last bit of the
      // volume's sum over the cells, which a run resumed on an adaptive grid repeats
      // (doc/checkpoints.md, "Exact").
      const double volume = fluid_solver->water_volume();
      statistics.add_value("water_volume", volume);
      statistics.add_value("water_outflow", fluid_solver->water_outflow);
      statistics.add_value("volume_drift", balance.drift(volume, fluid_solver->water_outflow));
      statistics.add_value("water_max_speed", fluid_solver->max_speed());
      statistics.add_value("skeleton_kinetic_energy", skeleton.kinetic_energy);
      statistics.add_value("skeleton_max_speed", skeleton.max_speed);
      statistics.add_value("skeleton_momentum_y", skeleton.momentum_y);
      // The granular mass's extent: its front (rightmost point) and top (highest point);
      // its porosity 1 - sum_p m_p / rho^s / sum_p V_p (where a dilatancy takes it).
      double front = -std::numeric_limits<double>::max(), top = front, volumes[2] = {0., 0.};
      engine->point_cloud().for_each_particle([&](const auto &particle) {
        front        = std::max(front, particle.get_location()[0]);
        top          = std::max(top, particle.get_location()[1]);
        const auto p = particle.get_properties();
        volumes[0] += p[soil::property::mass] / parameters.grain_density;
        volumes[1] += p[soil::property::volume];
      });
      dealii::Utilities::MPI::sum(dealii::ArrayView<const double>(volumes, 2),
                                  MPI_COMM_WORLD,
                                  dealii::ArrayView<double>(volumes, 2));
      statistics.add_value("skeleton_front", dealii::Utilities::MPI::max(front, MPI_COMM_WORLD));
      statistics.add_value("skeleton_top", dealii::Utilities::MPI::max(top, MPI_COMM_WORLD));
      statistics.add_value("skeleton_porosity",
                           volumes[1] > 0. ? 1. - volumes[0] / volumes[1] : 0.);
      statistics.add_value("flow_iterations", last_report.flow.iterations);
      // The consistent coupling's inner solves per GMRES product (relaxed as GMRES
      // converges: NodalGrainsCoupling::relax_products).
      if (parameters.consistent_drag)
        statistics.add_value("flow_inner_iterations", last_report.flow.inner_iterations);
      if (parameters.sub_cycling)
        statistics.add_value("skeleton_substeps", n_substeps);
      verification.add_statistics(statistics, info.time, fluid_solver->flow_field());
    }



    bool
    GranularWaterScene::finish(const StepInfo &info)
    {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          balance.print_summary(fluid_solver->water_outflow);
          fluid_output.print_probes();
        }
      // The grains that left through a free side of the grid (the engine drops them).
      const double lost = engine->state().lost_mass;
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 && lost > 0.)
        std::printf("Grains through the sides: %.6g kg/m out (%.6g m^2 of solid)\n",
                    lost,
                    lost / parameters.grain_density);
      return verification.finish(fluid_solver->flow_field(), engine->point_cloud(), info.time);
    }
  } // namespace granular
} // namespace slidewave
