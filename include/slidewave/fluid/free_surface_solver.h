#ifndef slidewave_fluid_free_surface_solver_h
#define slidewave_fluid_free_surface_solver_h

#include <deal.II/base/function.h>
#include <deal.II/fe/fe_system.h>
#include <memory>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/fluid/navier_stokes_system.h>
#include <slidewave/fluid/phase_field_system.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/finite_element_field.h>
#include <string>

namespace slidewave
{
  namespace fluid
  {
    /** What one step of the fluid did. */
    struct FluidStepReport
    {
      SolveReport flow, phase;
      double      gamma = 0.;
    };

    /**
     * The water and the air on the scene's background grid (paper 002's fluid): the flow
     * field (velocity and pressure, two states), the phase field, and their two linear
     * systems, all followers of the grid in that order, so that refinement, coarsening,
     * repartitioning and checkpoints carry every state and rebuild every system.
     *
     * One step (advance()): the grid's changes when due, the phase field from phi^n to
     * phi^{n+1} with the extrapolated velocity, then the flow with the density and
     * viscosity of phi at t^{n+theta}. The step is any length the caller gives (at most
     * stable_time_step()): a particle model coupled to the fluid sub-cycles its explicit
     * steps inside one fluid step and hands its fields over at the fluid's step (issue 27).
     */
    class FreeSurfaceSolver
    {
    public:
      /** The grid of the scene's parameters (the scene owns it). */
      static std::unique_ptr<grid::BackgroundGrid>
      make_grid(const FreeSurfaceParameters &parameters);

      FreeSurfaceSolver(const FreeSurfaceParameters &parameters, grid::BackgroundGrid &grid);

      /** Creates the grid (refined along the initial surface when adaptive) and the
       *  initial state: water at rest, phi from the signed distance to the water. */
      void
      setup(double start_time);

      /**
       * A moving porous solid in the flow, whose fields another physics on the grid sets
       * before every step (the skeleton of a granular mass, issue 27): creates the fluid
       * fraction, inverse permeability and solid flux (Q1 fields that follow the
       * grid), switches the porous terms on, and leaves the grid's changes to that
       * physics (advance() then changes nothing). Call before setup() or load(), instead
       * of a fixed porous structure. @p grain_density > 0: the solid's flux field is
       * (1 - n) v* of its predicted velocity and the flow eliminates its momentum (PorousMedium,
       * the semi-implicit drag); 0: of its velocity (explicit drag). @p nodal_grains (with
       * grain_density > 0; kept by the caller, filled before each step): the grains' nodal
       * momentum is solved with the water (NodalGrainsCoupling).
       */
      void
      enable_moving_solid(double grain_density = 0., const NodalGrains *nodal_grains = nullptr);

      /** The partitioning weight of each degree of freedom of the water and of the phase
       *  field (grid::FiniteElementField::set_weight_per_dof(); 100 unless set, against a
       *  cell's 1000). A scene whose cells also hold material points sets it in the points'
       *  units (GranularWaterScene). Counts from the next partition. */
      void
      set_partition_weight_per_dof(unsigned int weight);

      /** The grains' nodal coupling (enable_moving_solid() with nodal grains; null
       *  otherwise): after advance(), the grains' increment of the step. */
      const NodalGrainsCoupling *
      nodal_grains_coupling() const
      {
        return flow_system.nodal_grains_coupling();
      }

      /** The initial pressure is that of the initial fluids at rest (hydrostatic in the
       *  water) instead of 0 (a moving solid resting on the water's
       *  pressure from the start). Call before initialize(). */
      void
      start_hydrostatic()
      {
        hydrostatic_start = true;
      }

      /** The density of the initial fluid at @p point (water, air or between them in the
       *  interface) [kg/m^3]. */
      double
      initial_density(const dealii::Point<2> &point) const;

      /** The moving solid's fields (enable_moving_solid()), for the physics that sets
       *  them; call values_changed() after writing. */
      grid::FiniteElementField &
      solid_fraction_field()
      {
        return *fluid_fraction;
      }

      grid::FiniteElementField &
      inverse_permeability_field()
      {
        return *inverse_permeability;
      }

      grid::FiniteElementField &
      solid_flux_field()
      {
        return *solid_flux;
      }

      /** The flux (1 - n) v^n of the solid's velocity at the step's start, which the phase
       *  field reads when solid_flux_field() holds a predicted velocity (grain_density > 0
       *  in enable_moving_solid(); null otherwise: the phase field reads that one). */
      grid::FiniteElementField *
      start_flux_field()
      {
        return start_flux.get();
      }

      /** setup() on a grid another physics has created (collective). */
      void
      initialize(double start_time);

      /** Reads a checkpoint written by save() (the grid and every field). */
      void
      load(const std::string &prefix);

      void
      save(const std::string &prefix);

      double
      stable_time_step() const;

      FluidStepReport
      advance(double dt);

      /** gamma = factor x max(largest speed, sqrt(|g| h)). */
      double
      profile_velocity() const;

      double
      max_speed() const
      {
        return flow_system.max_speed();
      }

      /** The water's area [m^2 per m of width]: the integral of phi, of n phi in the
       *  pores of a solid (PhaseFieldSystem::water_volume()). */
      double
      water_volume() const
      {
        return phase_system.water_volume();
      }

      /** Whether every value of the fields is finite (collective). */
      bool
      state_is_finite() const;

      const grid::FiniteElementField &
      flow_field() const
      {
        return flow;
      }

      const grid::FiniteElementField &
      phase_field() const
      {
        return phase;
      }

      const grid::BackgroundGrid &
      background_grid() const
      {
        return grid;
      }

      /** @name The state a checkpoint keeps */
      /** @{ */
      double       time = 0., last_dt = 0.;
      unsigned int n_steps = 0;
      /** The water that left through the sides since the start (negative: entered). */
      double water_outflow = 0.;
      /** @} */

    private:
      /** gamma for the largest speed @p fastest. */
      double
      profile_velocity(double fastest) const;

      /** stable_time_step() for the largest speed @p fastest (max_speed()). */
      double
      stable_time_step(double fastest) const;

      /** phi of the initial water. */
      void
      set_initial_state();

      const FreeSurfaceParameters &parameters;
      grid::BackgroundGrid        &grid;
      grid::FiniteElementField     flow;
      grid::FiniteElementField     phase;
      NavierStokesSystem           flow_system;
      PhaseFieldSystem             phase_system;
      /** The initial pressure hydrostatic (start_hydrostatic()). */
      bool hydrostatic_start = false;
      /** phi of the initial water as a function (initial_density(), made at its first
       *  call). */
      mutable std::unique_ptr<dealii::Function<2>> initial_phase;
      /** The fixed porous structure's fields (only with 'Porous structure/Porosity'). */
      std::unique_ptr<grid::FiniteElementField> fluid_fraction, inverse_permeability;
      /** The moving solid's flux (1 - n) v_s (enable_moving_solid()), and that of its
       *  velocity at the step's start for the phase field (start_flux_field()). */
      std::unique_ptr<grid::FiniteElementField> solid_flux, start_flux;
    };
  } // namespace fluid
} // namespace slidewave

#endif
