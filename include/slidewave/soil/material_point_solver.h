#ifndef slidewave_soil_material_point_solver_h
#define slidewave_soil_material_point_solver_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/particles/particle_handler.h>
#include <functional>
#include <memory>
#include <set>
#include <slidewave/core/step_timeline.h>
#include <slidewave/engine/particle_engine.h>
#include <slidewave/engine/transfer_kernels.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/cell_patches.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/velocity_constraints.h>
#include <slidewave/particles/point_cloud.h>
#include <slidewave/particles/property_layout.h>
#include <slidewave/soil/material_point_parameters.h>
#include <slidewave/soil/soil_model.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace soil
  {
    /**
     * The explicit material point method of paper 000 (§3.1, Eqs. 13–23) in 2D plane
     * strain: material points in deal.II's ParticleHandler on a background grid of Q1 cells
     * (a parallel::distributed::Triangulation), lumped nodal mass, and per step
     *
     *   1. particle to grid: nodal mass, momentum, internal and external forces
     *      (Eqs. 14–17);
     *   2. grid update: accelerations and velocities (Eqs. 18–19), boundary conditions;
     *   3. grid to particle: velocities (PIC/FLIP blend) and positions (Eqs. 20–21);
     *   4. stresses from the updated nodal velocities (USL), or from velocities mapped back
     *      from the particles (MUSL), with the Jaumann rate (Eqs. 5–6) and, optionally, the
     *      B-bar treatment of the volumetric strain against locking.
     *
     * The solver is the soil's model (SoilModel) on the engine every particle model
     * shares (ParticleEngine<SoilModel>: point cloud, nodal workspace, constraints,
     * patches and the particle–grid cycle, attached to the scene's background grid, which
     * it takes by reference). It adds what is the soil's: its initial stress (uniform,
     * geostatic, gravity loading), its time step (Eq. 23), point forces, diagnostics.
     * Nothing is allocated per particle per step.
     */
    class MaterialPointSolver
    {
    public:
      /** The soil of @p parameters on the scene's @p grid (attaches to it). */
      MaterialPointSolver(const MaterialPointParameters &parameters, grid::BackgroundGrid &grid);

      /** The grid of the soil's parameters ('Grid', 'Adaptive grid', 'Load balancing'):
       *  what a scene of soil creates and shares. */
      static std::unique_ptr<grid::BackgroundGrid>
      make_grid(const MaterialPointParameters &parameters);

      /**
       * Creates the grid, fills the regions with material points and sets up their
       * initial stress (at time @p start_time; gravity loading runs before it):
       * create_points() then initialize_stress().
       */
      void
      setup(double start_time = 0.);

      /**
       * The first half of setup(): the grid (refined where the material will be and
       * partitioned by the points to come), the material points of the regions, the load
       * balance and the first full sort, at time @p start_time. A scene that loads the
       * points (the water of a coupled scene) sets their point forces after this and
       * before initialize_stress().
       */
      void
      create_points(double start_time = 0.);

      /**
       * The second half of setup(): the initial stress of the points ('Initial stress':
       * uniform, geostatic, or gravity loading). The geostatic stress carries the point
       * forces set since create_points(), and gravity loading holds them.
       */
      void
      initialize_stress();

      bool
      has_point_forces() const
      {
        return prm.point_forces;
      }

      /**
       * Sets the point force of every local material point to @p force(particle) [N/m];
       * they act in every following step until set again (needs
       * MaterialPointParameters::point_forces).
       */
      void
      set_point_forces(
        const std::function<dealii::Tensor<1, 2>(const dealii::Particles::ParticleAccessor<2> &)>
          &force);

      /** The sum of the point forces over all points (collective). */
      dealii::Tensor<1, 2>
      total_point_force() const;

      /**
       * Writes the grid and the material points (all properties) under @p prefix
       * (collective; deal.II's triangulation files plus attached particle data).
       */
      void
      save(const std::string &prefix);

      /**
       * Instead of setup(): rebuilds the grid and the material points written by save(),
       * on any number of ranks (collective).
       */
      void
      load(const std::string &prefix);

      /** What else determines the future of a run: time, lost mass, step counter. */
      using State = engine::ParticleEngine<SoilModel>::State;

      State
      state() const;

      void
      set_state(const State &state);

      /** h / max_p (c_p + |v_p|): Eq. 23 with alpha = 1 (collective); the stable step is
       *  max_time_step_multiplier times this. */
      double
      stability_limit() const;

      /** The time step of Eq. 23 (or the fixed one). */
      double
      stable_time_step() const;

      /**
       * Times the parts of each step in @p timer_output when 'Detailed timing' is on
       * (otherwise nothing); the timer must outlive the solver's steps.
       */
      void
      set_timer(dealii::TimerOutput &timer_output);

      /** One step of length @p dt. */
      void
      advance(double dt);

      /**
       * Checks the particles for non-finite values and non-positive volumes; returns a
       * description of the first bad one, or "" when all is well (collective).
       */
      std::string
      find_invalid_particle() const;

      /** Integral quantities, reduced over all ranks (collective). */
      using Integrals = SoilModel::Integrals;

      Integrals
      integrals() const;

      /**
       * Energies per unit thickness [J/m], reduced over all ranks (collective): kinetic,
       * elastic (p^2/(2K) + s:s/(4G) per unit volume) and the work done by gravity since
       * the start, sum m g.(x - x_0).
       */
      using EnergyBudget = SoilModel::EnergyBudget;

      EnergyBudget
      energy_budget() const;

      /** "material point ID at (x y) with speed S m/s" for the fastest point (collective). */
      std::string
      describe_fastest_particle() const;

      const dealii::parallel::distributed::Triangulation<2> &
      triangulation() const
      {
        return grid.triangulation();
      }

      const dealii::Particles::ParticleHandler<2> &
      particles() const
      {
        return engine.point_cloud().particles();
      }

      /** The points with their cells in the grid's order, for sums over them
       *  (particles::PointCloud::for_each_particle()). */
      const particles::PointCloud &
      point_cloud() const
      {
        return engine.point_cloud();
      }

      /** The points, writable: for a physics that loads them from outside (the water of a
       *  coupled scene writes the point forces the layout declares as external loads). */
      particles::PointCloud &
      points()
      {
        return engine.point_cloud();
      }

      const dealii::DoFHandler<2> &
      dof_handler() const
      {
        return grid.dof_handler();
      }

      /** Nodal velocities after the last grid update (ghosted). */
      const dealii::LinearAlgebra::distributed::Vector<double> &
      nodal_velocity(unsigned int component) const
      {
        return engine.nodal_workspace().velocity[component];
      }

      /** Lumped nodal masses of the last particle-to-grid transfer (owned entries). */
      const dealii::LinearAlgebra::distributed::Vector<double> &
      lumped_nodal_mass() const
      {
        return engine.nodal_workspace().nodal_mass;
      }

      /** Max over mean of the ranks' work (cells and points; collective). */
      double
      load_imbalance() const;

      /** How often the grid was adapted or repartitioned. */
      unsigned int
      n_grid_adaptations() const
      {
        return grid.n_changes();
      }

      /** The per-step, per-rank times of the parts of the step ('Step timeline'), or null
       * when it is off. */
      const core::StepTimeline *
      step_timeline() const
      {
        return timeline.get();
      }

      /** Steps whose points were relocated by deal.II's full sort ('Particle relocation'). */
      unsigned int
      n_full_particle_sorts() const
      {
        return engine.n_full_particle_sorts();
      }

      /** Time of the particles' state. */
      double
      current_time() const
      {
        return engine.time();
      }

      /**
       * Scatters the particles' mass and momentum to the grid and returns the totals over
       * all nodes {mass, momentum x, momentum y} (a check of the transfer; collective).
       */
      std::array<double, 3>
      nodal_totals();

      /** The background grid (triangulation, Q1 dofs, adaptivity, partitioning). */
      const grid::BackgroundGrid &
      background_grid() const
      {
        return grid;
      }

      /** What the points carry (names, vectors) for output, checkpoints and guards. */
      const particles::PropertyLayout &
      property_layout() const
      {
        return model.layout();
      }

    private:
      /** Gravity with heavy local damping, walls held, until gravity_loading_time. */
      void
      load_gravity();

      MaterialPointParameters           prm;
      SoilModel                         model;
      grid::BackgroundGrid             &grid;
      engine::ParticleEngine<SoilModel> engine;

      /** Per-step times of the parts ('Step timeline'): only allocated when on. */
      std::unique_ptr<core::StepTimeline> timeline;

      /** Gravity loading: every wall holds. */
      bool loading_gravity = false;
    };
  } // namespace soil

  extern template class engine::TransferKernels<soil::SoilModel>;
  extern template class engine::ParticleEngine<soil::SoilModel>;
} // namespace slidewave

#endif
