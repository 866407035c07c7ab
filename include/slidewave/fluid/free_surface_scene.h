#ifndef slidewave_fluid_free_surface_scene_h
#define slidewave_fluid_free_surface_scene_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/fluid/free_surface_output.h>
#include <slidewave/fluid/free_surface_parameters.h>
#include <slidewave/fluid/free_surface_solver.h>
#include <slidewave/fluid/water_balance.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /**
     * A scene of water and air only (Physics = free surface flow, subsection "Free
     * surface flow"): the stabilized finite-element flow with a phase-field surface on
     * the background grid (paper 002's fluid), its output, gauges, guards, statistics,
     * checkpoints and verification (doc/free-surface-flow.md).
     */
    class FreeSurfaceScene : public TimeSteppedScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      FreeSurfaceScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** What the scene needs in memory, from its counts, before it allocates them. */
      core::MemoryEstimate
      memory_estimate() const;

      bool
      run();

      std::string
      timer_prefix() const override
      {
        return "fluid";
      }

      std::vector<core::OutputFolder>
      output_folders() const override;

      void
      set_up(double start_time, dealii::TimerOutput &timer) override;

      /** Refuses a scene whose steps would not end: more than 10^7 steps at its first
       *  stable step. */
      void
      check_set_up() const override;

      std::string
      description() const override;

      void
      start(const StepInfo &info) override;

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
      void
      create_solver();

      /** The guards of the fields: finite, within the speed limit (RunFailure). Returns
       *  where the step is, for the water balance's guard. */
      std::string
      check_state(const StepInfo &info) const;

      const SceneParameters                &scene;
      FreeSurfaceParameters                 parameters;
      std::unique_ptr<grid::BackgroundGrid> grid;
      std::unique_ptr<FreeSurfaceSolver>    solver;
      FreeSurfaceOutput                     output;
      dealii::TimerOutput                  *timer = nullptr;
      FluidStepReport                       last_report;
      /** The wall time of the steps' parts since this process started [s]: flow
       *  assembly, its preconditioner, GMRES, the phase field (assembly and solve); the
       *  flow's GMRES iterations and preconditioner builds. */
      std::array<double, 4> part_times{};
      unsigned long long    flow_iterations = 0, preconditioner_builds = 0;
      /** The water volume at the start and the largest relative drift since. */
      WaterBalance balance{parameters};
      /** (time, value) of every step for the verification: the surge front (Martin and
       *  Moyce), the surface at the left wall (standing wave). */
      std::vector<std::pair<double, double>> verification_history;

      /** The verification's value now (collective). */
      double
      verification_value() const;

      /** The mean of the initial surface elevation over the grid's width. */
      double
      mean_surface_elevation() const;
    };
  } // namespace fluid
} // namespace slidewave

#endif
