#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/core/run_bounds.h>
#include <slidewave/granular/drag_law.h>
#include <slidewave/granular/granular_water_scene.h>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      /** Whether @p a and @p b agree to round-off relative to @p scale. */
      bool
      same(const double a, const double b, const double scale)
      {
        return std::abs(a - b) <= 1e-12 * scale;
      }
    } // namespace



    void
    GranularWaterScene::check_parameters() const
    {
      // One grid for both phases: the skeleton's and the water's must be the same.
      const double extent = (fluid_parameters.upper_right - fluid_parameters.lower_left).norm();
      for (unsigned int d = 0; d < 2; ++d)
        if (!same(soil_parameters.lower_left[d], fluid_parameters.lower_left[d], extent)
            || !same(soil_parameters.upper_right[d], fluid_parameters.upper_right[d], extent))
          throw InputError(soil_section + "/Grid",
                           "a domain unlike '" + fluid_section + "/Grid''s",
                           "the same lower left and upper right corners in both subsections "
                           "(the skeleton and the water share one grid)");
      if (!same(soil_parameters.cell_size, fluid_parameters.cell_size, fluid_parameters.cell_size))
        throw InputError(soil_section + "/Grid/Cell size",
                         to_string(soil_parameters.cell_size),
                         "the same as '" + fluid_section
                           + "/Grid/Cell size' = " + to_string(fluid_parameters.cell_size)
                           + " (the skeleton and the water share one grid)");
      const dealii::Tensor<1, 2> &g = fluid_parameters.fluid.gravity;
      for (unsigned int d = 0; d < 2; ++d)
        if (!same(soil_parameters.gravity[d], g[d], std::max(g.norm(), 1.)))
          throw InputError(soil_section + "/Gravity",
                           to_string(soil_parameters.gravity[0]) + ", "
                             + to_string(soil_parameters.gravity[1]),
                           "the same as '" + fluid_section + "/Fluids/Gravity' = " + to_string(g[0])
                             + ", " + to_string(g[1])
                             + " (one gravity acts on the grains and the water)");
      if (fluid_parameters.element_degree != 1)
        throw InputError(fluid_section + "/Finite elements/Degree",
                         std::to_string(fluid_parameters.element_degree),
                         "1 with Physics = granular water (the skeleton's nodes are the "
                         "vertices)");
      if (fluid_parameters.adaptive
          && soil_parameters.shape_function == grid::ShapeFunction::bspline)
        throw InputError(soil_section + "/Shape functions",
                         "bspline",
                         "q1, gimp or cpgimp with '" + fluid_section
                           + "/Adaptive grid/Enable = true' (a B-spline's domain is a cell of "
                             "the point's own cell's size, which would jump where the cells "
                             "change size)");
      for (const auto &solid : fluid_parameters.solids)
        if (fluid_parameters.adaptive)
          throw InputError(solid.path + "/Type",
                           "solid",
                           "none, roller or fixed with '" + fluid_section
                             + "/Adaptive grid/Enable = true' (a coarse cell could step over a "
                               "thin solid, and the two phases would hold a hanging node "
                               "differently)");
        else if (std::isfinite(solid.release_time))
          throw InputError(solid.path + "/Release time",
                           to_string(solid.release_time),
                           "'never' for a solid with Physics = granular water (it holds the "
                           "water too, whose constraints do not change during the run)");
      if (soil_parameters.adaptivity.enabled)
        throw InputError(soil_section + "/Adaptive grid/Enable",
                         "true",
                         "false with Physics = granular water: the grid both phases share "
                         "adapts by '"
                           + fluid_section
                           + "/Adaptive grid' (fine along the water surface and where the "
                             "grains are)");
      if (!fluid_parameters.porosity.empty())
        throw InputError(fluid_section + "/Porous structure/Porosity",
                         fluid_parameters.porosity,
                         "empty with Physics = granular water (the skeleton is the porous "
                         "solid)");
      if (soil_parameters.initial_stress == soil::InitialStress::gravity_loading)
        throw InputError(soil_section + "/Initial stress/Type",
                         "gravity loading",
                         "none, geostatic (the buoyant effective stress where the grains "
                         "are in water) or uniform with Physics = granular water");
      if (soil_parameters.prescribed_velocity)
        throw InputError(soil_section + "/Prescribed velocity",
                         "(set)",
                         "none with Physics = granular water");
      // The projection and the consistent coupling take the water's step as the grains'
      // (DragProjection, fluid::NodalGrainsCoupling).
      if ((parameters.projected_drag || parameters.consistent_drag) && parameters.sub_cycling)
        throw InputError(section + "/Drag coupling",
                         parameters.projected_drag ? "semi-implicit projected" :
                                                     "semi-implicit consistent",
                         "'semi-implicit' (the lumped coupling) or 'explicit' with 'Sub-cycling "
                         "= true': set one of them (the projected coupling, the default, and "
                         "the consistent one take the water's step as the grains', one "
                         "skeleton step per water step)");
      // APIC hands the grid's velocities back to the points nearly unfiltered, and the
      // projected grains take on their lumped nodal masses the increment of the water's
      // consistent matrix, which is up to three times larger on the shortest waves: where
      // the grains are permeable a standing wave of about four cells then grows
      // (doc/granular-water.md, "APIC and the projected coupling").
      if (parameters.projected_drag
          && soil_parameters.velocity_transfer == engine::VelocityTransfer::apic)
        throw InputError(soil_section + "/Velocity transfer",
                         "apic",
                         "flip with '" + section
                           + "/Drag coupling = semi-implicit projected' (the default): "
                             "with APIC the projected coupling lets a standing wave of about "
                             "four cells grow where the grains are permeable; apic only with "
                             "'semi-implicit consistent', 'semi-implicit' (lumped) or "
                             "'explicit' coupling "
                             "(doc/granular-water.md, \"APIC and the projected coupling\")");
      // The grains are denser than the skeleton: 0 < n_0 <= the porosity's cap (0.99).
      for (const auto &material : soil_parameters.materials)
        {
          const double n0 = 1. - material.density / parameters.grain_density;
          if (!(n0 > 0. && n0 <= DragLaw::porosity_cap))
            throw InputError(soil_section + "/Material '" + material.name + "'/Density",
                             to_string(material.density),
                             "a dry density (1 - n_0) rho^s between 0.01 and 1 times '" + section
                               + "/Grain density' = " + to_string(parameters.grain_density)
                               + " (an initial porosity in (0, 0.99])");
          // A suspension (n_0 > n_s) carries no stress: neither its own initial stress
          // nor, through 'geostatic', a weight on the points below it.
          if (n0 > parameters.suspension_porosity
              && soil_parameters.initial_stress != soil::InitialStress::none)
            throw InputError(soil_section + "/Initial stress/Type",
                             soil_parameters.initial_stress == soil::InitialStress::geostatic ?
                               "geostatic" :
                               "uniform",
                             "none with material '" + material.name
                               + "', which starts as a suspension (its porosity " + to_string(n0)
                               + " is above '" + section + "/Suspension porosity' = "
                               + to_string(parameters.suspension_porosity)
                               + "): its grains carry no stress");
          // A rate-dependent friction's grains and liquid are this scene's.
          const std::string path = soil_section + "/Material '" + material.name + "'";
          if (material.friction_law == materials::FrictionLaw::inertial
              && !same(material.grain_density, parameters.grain_density, parameters.grain_density))
            throw InputError(path + "/Grain density",
                             to_string(material.grain_density),
                             "the same as '" + section
                               + "/Grain density' = " + to_string(parameters.grain_density)
                               + " ('Friction law = inertial': the grains are the skeleton's)");
          const double water = fluid_parameters.fluid.water_viscosity;
          if (material.friction_law == materials::FrictionLaw::viscous
              && !same(material.fluid_viscosity, water, water))
            throw InputError(path + "/Fluid viscosity",
                             to_string(material.fluid_viscosity),
                             "the same as '" + fluid_section
                               + "/Fluids/Water viscosity' = " + to_string(water)
                               + " ('Friction law = viscous': the pore liquid is the water)");
        }
      if (parameters.exact_solution != GranularExactSolution::none)
        {
          // Settling's grains fall out of contact, its bed rests at n_s: any material.
          if (soil_parameters.materials.empty()
              || (parameters.exact_solution != GranularExactSolution::settling
                  && soil_parameters.materials[0].model
                       != materials::MaterialModel::linear_elastic))
            throw InputError(soil_parameters.materials.empty() ?
                               soil_section + "/Material 1" :
                               soil_parameters.materials[0].path + "/Model",
                             soil_parameters.materials.empty() ? "(none)" :
                             soil_parameters.materials[0].model
                                 == materials::MaterialModel::drucker_prager ?
                                                                 "drucker prager" :
                                                                 "hencky drucker prager",
                             parameters.exact_solution == GranularExactSolution::settling ?
                               "a material (any model) with 'Exact solution = settling'" :
                               "a linear elastic material with this exact solution");
          if (parameters.exact_solution == GranularExactSolution::seepage)
            {
              if (fluid_parameters.boundaries[3] != fluid::FlowBoundary::inflow)
                throw InputError(fluid_section + "/Boundary conditions/Top",
                                 "not inflow",
                                 "inflow with 'Exact solution = seepage' (the water enters "
                                 "at the top at its 'Inflow velocity')");
              if (fluid_parameters.fluid.gravity.norm() > 0.)
                throw InputError(fluid_section + "/Fluids/Gravity",
                                 to_string(fluid_parameters.fluid.gravity[0]) + ", "
                                   + to_string(fluid_parameters.fluid.gravity[1]),
                                 "0, 0 with 'Exact solution = seepage' (the gradient compared "
                                 "is the drag's alone)");
              // The exact gradient is that of this superficial velocity.
              if (!(GranularVerification::seepage_inflow(fluid_parameters, scene.end_time) < 0.))
                throw InputError(fluid_section + "/Boundary conditions/Inflow velocity",
                                 fluid_parameters.boundaries.inflow_velocity,
                                 "a downward velocity (a negative y component) at the middle "
                                 "of the top at the end time with 'Exact solution = seepage' "
                                 "(the exact gradient is that of this superficial velocity)");
            }
          if (parameters.exact_solution == GranularExactSolution::seepage)
            {
              if (fluid_parameters.boundaries[2] != fluid::FlowBoundary::open)
                throw InputError(fluid_section + "/Boundary conditions/Bottom",
                                 "not open",
                                 "open with 'Exact solution = seepage' (the water leaves at "
                                 "the bottom)");
              if (parameters.column_height < 4. * fluid_parameters.cell_size * (1. - 1e-9))
                throw InputError(section + "/Verification/Column height",
                                 to_string(parameters.column_height),
                                 "at least four cells ("
                                   + to_string(4. * fluid_parameters.cell_size)
                                   + " m) with 'Exact solution = seepage' (its middle half "
                                     "must hold two rows of nodes for the gradient)");
            }
          if (parameters.exact_solution == GranularExactSolution::settling)
            {
              const double n0
                = 1. - soil_parameters.materials[0].density / parameters.grain_density;
              if (!(n0 > parameters.suspension_porosity))
                throw InputError(soil_section + "/Material '" + soil_parameters.materials[0].name
                                   + "'/Density",
                                 to_string(soil_parameters.materials[0].density),
                                 "an initial porosity 1 - Density / '" + section
                                   + "/Grain density' = " + to_string(n0) + " above '" + section
                                   + "/Suspension porosity' = "
                                   + to_string(parameters.suspension_porosity)
                                   + " with 'Exact solution = settling' (the grains start "
                                     "out of contact)");
              if (parameters.forchheimer)
                throw InputError(section + "/Drag law",
                                 "Forchheimer",
                                 "Darcy with 'Exact solution = settling' (its fall is "
                                 "exponential with the linear drag)");
              if (soil_parameters.boundaries[2] == grid::GridBoundary::free)
                throw InputError(soil_section + "/Boundary conditions/Bottom",
                                 "free",
                                 "roller or fixed with 'Exact solution = settling' (the bed "
                                 "forms on the floor; through a free bottom the grains leave "
                                 "the grid)");
            }
          if (parameters.exact_solution == GranularExactSolution::terzaghi
              && parameters.permeability_law != PermeabilityLaw::constant)
            throw InputError(section + "/Permeability law",
                             "Kozeny-Carman",
                             "constant with 'Exact solution = Terzaghi' (its c_v is constant)");
        }
      core::check_step_count(scene,
                             soil_parameters.fixed_time_step,
                             soil_section + "/Fixed time step",
                             to_string(soil_parameters.fixed_time_step),
                             "'Fixed time step'");
    }



    void
    GranularWaterScene::after_step(const StepInfo &info)
    {
      dealii::TimerOutput::Scope scope(*timer, "granular: checks");
      const std::string          where
        = "at step " + std::to_string(info.step) + ", t = " + to_string(info.time) + " s: ";
      if (!fluid_solver->state_is_finite())
        throw RunFailure(where
                         + "the water's velocity, pressure or phase field is not finite "
                           "(reduce the time step)");
      if (info.step % check_interval == 0 || info.is_output_time || info.at_end)
        {
          const std::string bad = model->find_invalid_particle(engine->point_cloud());
          if (!bad.empty())
            throw RunFailure(where + bad);
          // The water's guards ('Free surface flow/Guards'), at the skeleton's checks: the
          // volume's integral is a pass over the cells, like the points' check.
          const double speed = fluid_solver->max_speed();
          if (fluid_parameters.max_speed > 0. && speed > fluid_parameters.max_speed)
            throw RunFailure(where + "the water's largest speed, " + to_string(speed)
                             + " m/s, exceeds 'Free surface flow/Guards/Maximum speed' = "
                             + to_string(fluid_parameters.max_speed) + " m/s");
          balance.check(where, fluid_solver->water_volume(), fluid_solver->water_outflow);
        }
      fluid_output.record_gauges(*fluid_solver, info.time);
      verification.after_step(info.time, fluid_solver->flow_field());
    }
  } // namespace granular
} // namespace slidewave
