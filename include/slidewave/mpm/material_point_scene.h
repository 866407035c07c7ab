#ifndef slidewave_mpm_material_point_scene_h
#define slidewave_mpm_material_point_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/mpm/material_point_solver.h>
#include <slidewave/mpm/particle_output.h>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace mpm
  {
    /**
     * A scene of soil or rock only (Physics = material points): builds the grid and the
     * material points from subsection "Material points", runs the time loop, and writes the
     * particles (.pvtu with a .pvd time series) and statistics.
     */
    class MaterialPointScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      MaterialPointScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** Runs the scene; throws RunFailure when a material point becomes invalid. */
      bool
      run();

    private:
      /** The time loop; throws RunFailure when the state becomes invalid. */
      bool
      run_time_loop(dealii::TimerOutput &timer);

      /** The background grid with the nodal mass and velocity of the last step. */
      void
      write_grid_state(unsigned int index, double time);

      /** The state of the time loop (saved in checkpoints). */
      struct LoopState
      {
        double       time = 0., next_output = 0., max_error = 0.;
        unsigned int step = 0, output_index = 0;
      };

      /** Writes OUTPUT/checkpoint atomically, keeping the previous one (collective). */
      void
      write_checkpoint(const LoopState &loop) const;

      /** Loads the newest checkpoint instead of setting up (collective). */
      void
      resume(LoopState &loop);

      /** Physics, grid and materials, which a checkpoint must share with the scene. */
      std::string
      checkpoint_signature() const;

      /** The run-time guards; throws RunFailure (collective). */
      void
      check_state(unsigned int step, double time) const;

      void
      add_statistics(Statistics &statistics, unsigned int step, double time, double dt) const;

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
        rigid_rotation
      };

      /** Rigid rotation: the largest stress error against R sigma_0 R^T over |sigma_0|, and
       *  the largest distance [m] of a point from its rigidly rotated position. */
      std::array<double, 2>
      rotation_errors(double time) const;

      double           rotation_rate = 1.;
      dealii::Point<2> rotation_centre;

      const SceneParameters  &scene;
      ExactSolution           exact_solution = ExactSolution::none;
      double                  bar_length = 25., bar_amplitude = 0.1, column_height = 1.;
      double                  tolerance = 0.;
      MaterialPointParameters parameters;
      std::unique_ptr<MaterialPointSolver>        solver;
      ParticleOutput                              particle_output;
      std::vector<std::pair<double, std::string>> grid_files;
      bool                                        write_grid     = false;
      unsigned int                                check_interval = 10;
      /** Kinetic + elastic energy at the start, and the total mass (for the guards). */
      double initial_energy = 0., total_mass = 0.;
    };
  } // namespace mpm
} // namespace slidewave

#endif
