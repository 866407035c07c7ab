#ifndef slidewave_water_water_scene_h
#define slidewave_water_water_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/water/dam_break_solutions.h>
#include <slidewave/water/shallow_water_1d.h>
#include <slidewave/water/water_output.h>
#include <slidewave/water/water_state_parameters.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace water
  {
    /**
     * A scene with only water: the 1D shallow water column on its own (Physics = shallow
     * water). Builds the mesh, the bed, the initial state and the boundaries from subsection
     * "Shallow water", runs the time loop, and writes profiles, gauges, statistics and, when
     * an exact solution is named, the error against it.
     *
     * Every rank solves the (small) 1D problem redundantly and only rank 0 writes, so the
     * results do not depend on the number of MPI ranks.
     */
    class WaterScene : public TimeSteppedScene
    {
    public:
      /** Declares subsection "Shallow water" and everything in it. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks all parameters; throws InputError on bad input. */
      WaterScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** What the scene needs in memory, from its counts, before it allocates them. */
      core::MemoryEstimate
      memory_estimate() const;

      /**
       * Runs the scene. Throws RunFailure when the state becomes invalid; returns false
       * when the error against the exact solution exceeds a requested tolerance.
       */
      bool
      run();

      /** The solver (for tests and the coupling). */
      const ShallowWater1D &
      solver() const
      {
        return *water;
      }

      /** @name The scene's part of the time loop (TimeSteppedScene) */
      /** @{ */
      std::string
      timer_prefix() const override
      {
        return "water";
      }

      std::vector<core::OutputFolder>
      output_folders() const override;

      void
      set_up(double start_time, dealii::TimerOutput &timer) override;

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

      /** The mesh (cells and ends), which a checkpoint must share with the scene. */
      std::string
      checkpoint_signature() const override;

      std::vector<std::string>
      growing_files() const override;

      void
      save(io::CheckpointRecord &record) override;

      void
      resume(const io::CheckpointRecord &record,
             const std::string          &prefix,
             dealii::TimerOutput        &timer) override;
      /** @} */

    private:
      enum class ExactSolution
      {
        none,
        dam_break,
        initial_state,
        thacker,
        still_level
      };

      /** Reads subsection "Verification": the exact solution (its constants, with the
       *  @p gravity of the solver) and the tolerances; throws InputError on bad input. */
      void
      parse_verification(dealii::ParameterHandler &prm, double gravity);

      void
      write_profile(unsigned int index, double time) const;

      /** Compares with the exact solution at @p time; returns false if out of tolerance. */
      bool
      report_errors(double time) const;

      void
      exact_state(double x, double time, double &depth, double &discharge) const;

      const SceneParameters          &scene;
      std::unique_ptr<ShallowWater1D> water;

      /** B(x, t) of a bed that moves in time ('Bed/Time dependent'); null for a fixed bed.
       *  Re-sampled before every step, as the coupled scenes replace the bed. */
      std::unique_ptr<BedElevation> moving_bed;
      std::vector<double>           bed_work;

      GaugeRecorder gauges;

      ExactSolution                   exact_solution = ExactSolution::none;
      std::optional<DamBreakSolution> dam_break;
      std::optional<ThackerSolution>  thacker;
      std::vector<double>             initial_depth, initial_discharge;
      double                          tolerance_l1_depth = 0.;
      double                          tolerance_linf     = 0.;
      double                          tolerance_volume   = 0.;

      bool                 is_writer = false;
      std::string          water_directory;
      double               initial_volume     = 0.;
      double               max_volume_balance = 0.;
      dealii::TimerOutput *timer              = nullptr;
    };
  } // namespace water
} // namespace slidewave

#endif
