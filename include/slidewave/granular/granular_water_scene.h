#ifndef slidewave_granular_granular_water_scene_h
#define slidewave_granular_granular_water_scene_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/engine/particle_engine.h>
#include <slidewave/fluid/free_surface_output.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/fluid/free_surface_solver.h>
#include <slidewave/fluid/water_balance.h>
#include <slidewave/granular/drag_projection.h>
#include <slidewave/granular/granular_verification.h>
#include <slidewave/granular/granular_water_parameters.h>
#include <slidewave/granular/porous_skeleton_model.h>
#include <slidewave/granular/skeleton_fluid_exchange.h>
#include <slidewave/io/particle_output.h>
#include <slidewave/soil/material_point_parameters.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    /**
     * A granular skeleton in water and air (Physics = granular water; paper 002): the
     * skeleton's material points (PorousSkeletonModel on the particle engine, subsection
     * "Material points") and the free-surface flow with the skeleton as a moving porous
     * solid (subsection "Free surface flow") on one background grid, exchanged at its
     * nodes (SkeletonFluidExchange; subsection "Granular water"). One step (§3.5): the
     * points to the grid (mass, momentum, effective-stress forces, solid volume, drag),
     * the water's fields from them, the water's step (phase field, then flow), the
     * water's force on the grains at the nodes, the grains' grid update and the points'
     * update. doc/granular-water.md.
     */
    class GranularWaterScene : public TimeSteppedScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      GranularWaterScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      core::MemoryEstimate
      memory_estimate() const;

      bool
      run();

      std::string
      timer_prefix() const override
      {
        return "granular";
      }

      std::vector<core::OutputFolder>
      output_folders() const override;

      void
      set_up(double start_time, dealii::TimerOutput &timer) override;

      void
      check_set_up() const override;

      std::string
      description() const override;

      double
      stable_time_step() override;

      void
      advance(const StepInfo &info) override;

      void
      after_step(const StepInfo &info) override;

      void
      write_output(unsigned int index, double time) override;

      void
      add_statistics(Statistics &statistics, const StepInfo &info) const override;

      bool
      finish(const StepInfo &info) override;

      std::string
      checkpoint_signature() const override;

      std::vector<std::string>
      growing_files() const override;

      void
      save(io::CheckpointRecord &record) override;

      void
      save_data(const std::string &prefix) override;

      void
      resume(const io::CheckpointRecord &record,
             const std::string          &prefix,
             dealii::TimerOutput        &timer) override;

    private:
      /** The scene's subsections: its own, the skeleton's and the water's. */
      static inline const std::string section       = "Granular water";
      static inline const std::string soil_section  = "Material points";
      static inline const std::string fluid_section = "Free surface flow";

      /** Refuses what the two phases on one grid cannot do (InputError naming the
       *  parameter): granular_water_scene_checks.cc. */
      void
      check_parameters() const;

      using Engine = engine::ParticleEngine<PorousSkeletonModel>;

      /** The grid, the water's solver and the skeleton's engine, attached in that order. */
      void
      create_solvers();

      /** The point forces of 'Top load' on the top row of points. */
      void
      apply_top_load();

      /** The water's force on the grains of the semi-implicit coupling (projected or
       *  consistent) into water_force, after the water's step of length @p dt, with the
       *  skeleton's fields @p fields of this step. */
      void
      project_water_force(const SkeletonFields &fields, double dt);

      /** The grains' nodes of this step for the consistent coupling: 1 on the owned nodes
       *  with more than the empty mass, 0 on held components and hanging nodes. */
      void
      prepare_nodal_grains();

      /** The water's fields the skeleton hands over (SkeletonFluidExchange::to_fluid()). */
      SkeletonFields
      skeleton_fields();

      /** h / max(c_p + |v_p|): the skeleton's P-wave limit before the multiplier
       *  (collective). */
      double
      skeleton_limit() const;

      /** The explicit coupling's time scale rho^s (1 - n) k / mu, infinite with the
       *  semi-implicit coupling (collective). */
      double
      coupling_limit() const;

      /** min(skeleton_limit(), coupling_limit()) (collective). */
      double
      stability_limit() const;

      /** The step (of the water, with sub-cycling): the fixed one, or the least of the
       *  water's Courant limit and 'Time step multiplier' times stability_limit() (times
       *  the coupling's time scale only, with sub-cycling) (collective). */
      double
      step_limit() const;

      const SceneParameters                    &scene;
      soil::MaterialPointParameters             soil_parameters;
      fluid::FreeSurfaceParameters              fluid_parameters;
      GranularWaterParameters                   parameters;
      std::unique_ptr<grid::BackgroundGrid>     grid;
      std::unique_ptr<fluid::FreeSurfaceSolver> fluid_solver;
      std::unique_ptr<PorousSkeletonModel>      model;
      std::unique_ptr<Engine>                   engine;
      std::unique_ptr<SkeletonFluidExchange>    exchange;
      /** The grains' increment of the semi-implicit coupling (projected; null otherwise). */
      std::unique_ptr<DragProjection> projection;
      /** The water's force on the grains at the nodes (reused every step). */
      std::array<grid::NodalWorkspace::Vector, 2> water_force;
      /** The water's nodal drag W_I of the semi-implicit coupling. */
      grid::NodalWorkspace::Vector water_drag;
      /** The grains' nodes the water's solve takes with it ('semi-implicit consistent';
       *  prepare_nodal_grains()), and which of their components it solves for. */
      fluid::NodalGrains                          nodal_grains;
      std::array<grid::NodalWorkspace::Vector, 2> grains_free;
      io::ParticleOutput                          particle_output;
      fluid::FreeSurfaceOutput                    fluid_output;
      dealii::TimerOutput                        *timer = nullptr;
      fluid::FluidStepReport                      last_report;
      /** The water's volume against its start and what left through the sides. */
      fluid::WaterBalance balance{fluid_parameters};
      unsigned int        check_interval = 10;
      /** The skeleton's sub-steps in the last step. */
      unsigned int         n_substeps = 1;
      GranularVerification verification;
    };
  } // namespace granular
} // namespace slidewave

#endif
