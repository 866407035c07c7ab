#ifndef slidewave_soil_material_point_scene_h
#define slidewave_soil_material_point_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/io/particle_output.h>
#include <slidewave/soil/material_point_solver.h>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace soil
  {
    /**
     * A scene of soil or rock only (Physics = material points): builds the grid and the
     * material points from subsection "Material points", runs the time loop, and writes the
     * particles (.pvtu with a .pvd time series) and statistics.
     */
    class MaterialPointScene : public TimeSteppedScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      MaterialPointScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** What the scene needs in memory, from its counts, before it allocates them. */
      core::MemoryEstimate
      memory_estimate() const;

      /** Runs the scene; throws RunFailure when a material point becomes invalid. */
      bool
      run();

      /** @name The scene's part of the time loop (TimeSteppedScene) */
      /** @{ */
      std::string
      timer_prefix() const override
      {
        return "mpm";
      }

      std::vector<core::OutputFolder>
      output_folders() const override;

      void
      set_up(double start_time, dealii::TimerOutput &timer) override;

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

      /** Physics, grid and materials, which a checkpoint must share with the scene. */
      std::string
      checkpoint_signature() const override;

      void
      save(io::CheckpointRecord &record) override;

      void
      save_data(const std::string &prefix) override;

      void
      resume(const io::CheckpointRecord &record,
             const std::string          &prefix,
             dealii::TimerOutput        &timer) override;
      /** @} */

    private:
      /** The solver, with the timer of the run. */
      void
      create_solver(dealii::TimerOutput &timer);

      /** The run-time guards; throws RunFailure (collective). */
      void
      check_state(unsigned int step, double time) const;

      /** Error of the centre-of-mass velocity against the vibrating bar's exact value. */
      double
      bar_velocity_error(double time) const;

      /** Normalized error of sigma_yy against the self-weight column's exact value. */
      double
      column_stress_error() const;

      enum class ExactSolution
      {
        none,
        bar_vibration,
        self_weight_column,
        rigid_rotation,
        homogeneous_deformation
      };

      /** Rigid rotation: the largest stress error against R sigma_0 R^T over |sigma_0|, and
       *  the largest distance [m] of a point from its rigidly rotated position. */
      std::array<double, 2>
      rotation_errors(double time) const;

      /** Homogeneous deformation: the largest stress error of a point against the closed
       *  form (hencky_homogeneous_state()) over |sigma_exact|; prints the exact state. */
      double
      homogeneous_deformation_error(double time) const;

      /** The constant velocity gradient of 'homogeneous deformation' [1/s]. */
      dealii::Tensor<2, 2> velocity_gradient;

      double           rotation_rate = 1.;
      dealii::Point<2> rotation_centre;

      const SceneParameters  &scene;
      ExactSolution           exact_solution = ExactSolution::none;
      double                  bar_length = 25., bar_amplitude = 0.1;
      double                  column_height = 1.;
      double                  tolerance     = 0.;
      MaterialPointParameters parameters;
      /** The scene's background grid, shared by what lives on it (declared before the
       *  solver: it outlives it). */
      std::unique_ptr<grid::BackgroundGrid> grid;
      std::unique_ptr<MaterialPointSolver>  solver;
      dealii::TimerOutput                  *timer = nullptr;
      io::ParticleOutput                    particle_output;
      io::GridOutput                        grid_output;
      bool                                  write_grid     = false;
      unsigned int                          check_interval = 10;
      /** Kinetic + elastic energy at the start, and the total mass (for the guards). */
      double initial_energy = 0., total_mass = 0.;
      /** The largest error against the exact solution so far (bar vibration). */
      double max_error = 0.;
      /** The step this process started from (0, or the checkpoint's). */
      unsigned int first_step = 0;
    };
  } // namespace soil
} // namespace slidewave

#endif
