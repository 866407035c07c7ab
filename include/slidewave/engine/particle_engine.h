#ifndef slidewave_engine_particle_engine_h
#define slidewave_engine_particle_engine_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/timer.h>
#include <optional>
#include <slidewave/core/step_timeline.h>
#include <slidewave/engine/transfer_kernels.h>
#include <slidewave/engine/velocity_transfer.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/cell_patches.h>
#include <slidewave/grid/grid_boundary.h>
#include <slidewave/grid/nodal_workspace.h>
#include <slidewave/grid/rigid_solid.h>
#include <slidewave/grid/rigid_wall.h>
#include <slidewave/grid/shape_functions.h>
#include <slidewave/grid/velocity_constraints.h>
#include <slidewave/particles/material_region.h>
#include <slidewave/particles/point_cloud.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace engine
  {
    /**
     * The one composition of the explicit material point method that every particle
     * model shares (the soil of paper 000, the depth-averaged columns of paper 001, the
     * porous skeleton of paper 002 to come): on the scene's background grid, which it
     * takes by reference, it attaches its followers (the point cloud, the nodal
     * workspace, the velocity constraints, the cell patches, in that order: rebuilt in
     * that order after a grid change) and runs the particle–grid cycle of the model
     * (TransferKernels<Model>) with its cadence: the grid's changes when due, the walls,
     * particles to grid, the grid update, grid to particles (USL, or MUSL's re-map and
     * update), and the relocation of the points (within their patches, or deal.II's full
     * sort). It also holds the state every such run has besides its points: time, step
     * counter, lost mass.
     *
     * A template on the model, instantiated in the model's source next to its kernels
     * (particle_engine.templates.h). A model's solver (the soil's MaterialPointSolver,
     * DepthAveragedSolver) owns the model and an engine, and adds only what is the
     * model's: its initial state, its time-step limit, its diagnostics.
     */
    template <class Model>
    class ParticleEngine
    {
    public:
      /** The engine's settings that are not the model's. */
      struct Settings
      {
        grid::ShapeFunction shape_function = grid::ShapeFunction::q1;
        double              flip_fraction  = 0.99;
        /** > 0: flip_fraction is the blend of a step of this multiple of the model's stable
         *  step (stability_limit()), and a step of another length dt blends
         *  flip_fraction^(dt / dt_ref): PIC's damping is then a rate, not a share of every
         *  step, and the scheme converges as the step shrinks (the same blend at the
         *  reference step; pure PIC and pure FLIP unchanged). 0: the same blend every
         *  step. */
        double flip_reference_multiplier = 0.;
        /** The points' velocity transfer: the FLIP blend above, or APIC (the model's
         *  layout then holds affine_property_names(); flip_fraction is unused). */
        VelocityTransfer velocity_transfer = VelocityTransfer::flip;
        /** Modified update stress last: re-map the velocities before the update. */
        bool musl = false;
        /** Relocate the points by deal.II's full sort every step. */
        bool full_sort_every_step = false;
        /** Keep the positions of the owned nodes (a prescribed velocity needs them). */
        bool with_node_positions = false;
        /** Kinematic mode: the nodal velocities are this field (null: off). */
        dealii::FunctionParser<2> *prescribed_velocity = nullptr;
        /** 'Particle weight' of a point against a cell's 1000 in the partition. */
        unsigned int particle_weight = 1000000;
        /** The prefix of the timer sections ("mpm step"). */
        std::string timer_name = "mpm step";
      };

      /** Time, lost mass (summed over the ranks) and step counter. */
      struct State
      {
        double       time = 0., lost_mass = 0.;
        unsigned int n_steps = 0;
      };

      /**
       * The engine of @p model on @p grid: attaches its followers. @p sides: the grid
       * sides' conditions; @p walls, @p solids: rigid walls and solids (empty: none).
       */
      ParticleEngine(grid::BackgroundGrid                    &grid,
                     const Model                             &model,
                     const std::array<grid::GridBoundary, 4> &sides,
                     const std::vector<grid::RigidWall>      &walls,
                     const std::vector<grid::RigidSolid>     &solids,
                     const Settings                          &settings);

      /**
       * Set-up at @p start_time: the grid's cells (refined and partitioned by the points
       * that @p regions will get, @p n per direction), the points (@p fill gives their
       * properties), a repartition by the points if unbalanced and a first full sort.
       */
      void
      create_points(double                                        start_time,
                    const std::vector<particles::MaterialRegion> &regions,
                    unsigned int                                  n,
                    const particles::PointCloud::PropertyFill    &fill);

      /** Writes the grid and the points under @p prefix (collective). */
      void
      save(const std::string &prefix) const;

      /** Instead of create_points(): the grid and the points written by save(), on any
       *  number of ranks (collective). */
      void
      load(const std::string &prefix);

      State
      state() const;

      void
      set_state(const State &state);

      /** One step of length @p dt; @p hold_walls: every rigid wall holds (gravity
       *  loading). The same as begin_step() and finish_step(). */
      void
      advance(double dt, bool hold_walls = false);

      /**
       * The first half of a step, for a physics coupled at the nodes (the water of a
       * granular mass, issue 27): the grid's changes when due, the walls, the points to
       * the grid. The nodal mass, momentum, force and the model's fields then hold this
       * step's sums (owned nodes), and add_nodal_forces() may add to the force before
       * finish_step() (collective).
       */
      void
      begin_step(bool hold_walls = false);

      /** The second half of a step of length @p dt begun by begin_step(): the grid update,
       *  the grid to the points, the stresses and the points' relocation (collective). */
      void
      finish_step(double dt);

      /**
       * Adds @p force (per component, a vector with the nodal workspace's layout whose
       * owned entries hold the totals) to the nodal force of the owned nodes that carry
       * mass this step, between begin_step() and finish_step().
       */
      void
      add_nodal_forces(const std::array<grid::NodalWorkspace::Vector, 2> &force);

      /** The model's nodal field @p f, writable: a physics coupled at the nodes writes a
       *  field the points gather (between begin_step() and finish_step()) and leaves its
       *  ghost entries zero after finish_step(), as the next scatter expects. */
      grid::NodalWorkspace::Vector &
      model_field(const unsigned int f)
      {
        return nodes.fields[f];
      }

      /** The velocity conditions of the grid's sides and walls. */
      const grid::VelocityConstraints &
      velocity_constraints() const
      {
        return constraints;
      }

      /** max_p (c_p + |v_p|) over all ranks (collective). */
      double
      max_signal_speed() const;

      /** The model's stable step (Model::stability_limit) for the fastest point
       *  (max_signal_speed()) and the grid's finest cells (collective). */
      double
      stability_limit() const;

      /** The FLIP fraction of a step of length @p dt (Settings::flip_reference_multiplier),
       *  between begin_step() and finish_step(). */
      double
      flip_fraction_of_step(double dt) const;

      /** Whether the FLIP blend depends on the step (Settings::flip_reference_multiplier,
       *  a blend strictly between PIC and FLIP; never with APIC). */
      bool
      blends_by_rate() const;

      /** The points to the grid alone, without a step (no grid change, no walls' update):
       *  the nodal sums of the current state, for a physics coupled at the nodes to read
       *  before the first step (collective). */
      void
      scatter_points()
      {
        kernels.particles_to_grid();
      }

      /** Scatters the points and returns the nodal totals {mass, momentum x, momentum y}
       *  (a check of the transfer; collective). */
      std::array<double, 3>
      nodal_totals();

      /** Times the parts of each step in @p timer_output (null: nowhere). */
      void
      set_timer(dealii::TimerOutput *timer_output)
      {
        timer = timer_output;
      }

      /** Per-step, per-rank times of the parts of the step (null: none). */
      void
      set_timeline(core::StepTimeline *step_timeline)
      {
        timeline = step_timeline;
        kernels.set_timeline(step_timeline);
      }

      double
      time() const
      {
        return current_time;
      }

      void
      set_time(const double t)
      {
        current_time = t;
      }

      /** Steps whose points were relocated by deal.II's full sort. */
      unsigned int
      n_full_particle_sorts() const
      {
        return n_full_sorts;
      }

      particles::PointCloud &
      point_cloud()
      {
        return cloud;
      }

      const particles::PointCloud &
      point_cloud() const
      {
        return cloud;
      }

      const grid::NodalWorkspace &
      nodal_workspace() const
      {
        return nodes;
      }

      const grid::BackgroundGrid &
      background_grid() const
      {
        return grid;
      }

    private:
      /** The end of a part of the step for the step timeline, when it is on. */
      void
      lap(const core::StepTimeline::Part part)
      {
        if (timeline)
          timeline->lap(part);
      }

      /** Starts the timer section @p name of the step (ends the one before), when a
       *  timer is given. */
      void
      start_part(const char *name);

      /** The model's last look at the points at their new positions, before they are
       *  relocated (Model::finish_point), and the points it splits (collective). */
      void
      finish_points();

      /** Puts the points at their new positions in their cells (collective). */
      void
      relocate();

      grid::BackgroundGrid     &grid;
      const Model              &model;
      const Settings            settings;
      particles::PointCloud     cloud;
      grid::NodalWorkspace      nodes;
      grid::VelocityConstraints constraints;
      grid::CellPatches         patches;
      TransferKernels<Model>    kernels;

      double       current_time = 0.;
      unsigned int n_steps = 0, n_full_sorts = 0;
      /** Settings::flip_reference_multiplier times stability_limit() at the start of this
       *  step (begin_step(), only when the FLIP blend is a rate). */
      double               reference_step = 0.;
      dealii::TimerOutput *timer          = nullptr;
      core::StepTimeline  *timeline       = nullptr;
      /** Scratch of finish_points(), kept between steps (no allocation once grown): the
       *  new points, their properties and positions, and one point's properties. */
      std::vector<particles::PointCloud::NewPoint> new_points;
      std::vector<double>                          new_point_values, new_point_buffer;
      std::vector<dealii::Point<2>>                new_point_positions;
      /** The timer section of the part of the step under way. */
      std::optional<dealii::TimerOutput::Scope> part;
    };
  } // namespace engine
} // namespace slidewave

#endif
