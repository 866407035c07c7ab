#ifndef slidewave_depth_averaged_depth_averaged_scene_h
#define slidewave_depth_averaged_depth_averaged_scene_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <limits>
#include <memory>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <slidewave/depth_averaged/depth_averaged_solver.h>
#include <slidewave/depth_averaged/hazard_maps.h>
#include <slidewave/io/particle_output.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * A scene of the depth-averaged flow (`Physics = depth averaged`, paper 001): the
     * solver, its guards (non-finite state, depth not positive, points through a wall,
     * energy), its statistics (mass, lost mass, momentum, energies, speed, depth, extent,
     * covered area; on request the nodal totals against the points' and the errors against
     * an exact solution), its output (points, and the depth and surface on the grid) and
     * its checkpoints.
     */
    class DepthAveragedScene : public TimeSteppedScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      DepthAveragedScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** What the scene needs in memory, from its counts, before it allocates them. */
      core::MemoryEstimate
      memory_estimate() const;

      /** Runs the scene; false when a verification tolerance was exceeded. */
      bool
      run();

      std::string
      timer_prefix() const override
      {
        return "depth averaged";
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

    private:
      enum class ExactSolution
      {
        none,
        still_state,      ///< material at rest at the release's surface
        dam_break,        ///< Ritter's or Stoker's dam break along x, or Mangeney's on a slope
        sliding_block,    ///< a slab sliding down a plane with Coulomb friction
        rigid_translation ///< every column keeps its depth and its initial velocity
      };

      void
      create_solver(dealii::TimerOutput &timer);

      /** The guards; throws RunFailure. */
      void
      check_state(unsigned int step, double time) const;

      /** The still state's errors (L1, L-infinity of h, hu, hv). */
      DepthAveragedModel::StillStateErrors
      still_state_errors() const;

      /** The dam break: sum |h_i - h(x_i, t)| a_i over sum h(x_i, t) a_i at the nodes;
       *  on a slope (from the tail of the rarefaction on), the velocity's
       *  sum |u_i - u(x_i, t)| h(x_i, t) a_i over sum |u(x_i, t)| h(x_i, t) a_i (0 on a
       *  flat bed); and the columns' own sum_p |h_p - h(x_p, t)| A_p over the same
       *  sum h(x_i, t) a_i, with A_p = V_p / h_p (doc/depth-averaged.md, Speed and
       *  accuracy: why both), only @p with_columns (0 otherwise). */
      std::array<double, 3>
      dam_break_errors(double time, bool with_columns = false) const;

      /** The dry-bed dam break's front (Ritter, or on a slope): the largest x of a node
       *  whose depth exceeds 1 % of 'Left depth', and the same point of the exact
       *  solution (collective). */
      std::array<double, 2>
      dry_front(double time) const;

      /** The sliding block: |momentum_x / (M t) - a| / a, a the exact horizontal
       *  acceleration (0 at t = 0). */
      double
      sliding_block_error(double time) const;

      /** The rigid translation: the columns' depth against their depth at the start and
       *  their positions against x_p0 + v_p0 t (DepthAveragedModel::translation_errors). */
      DepthAveragedModel::TranslationErrors
      translation_errors(double time) const;

      /** The nodal totals against the points': relative errors of mass and momentum. */
      std::array<double, 2>
      conservation_errors() const;

      /** conservation_errors() now, kept for the statistics and the largest so far. */
      void
      record_conservation();

      /** points/points_NNNNN.csv (rank 0 writes what every rank has). */
      void
      write_point_table(unsigned int index) const;

      const SceneParameters  &scene;
      DepthAveragedParameters parameters;
      /** The scene's background grid, shared by what lives on it (declared before the
       *  solver: it outlives it). */
      std::unique_ptr<grid::BackgroundGrid> grid;
      std::unique_ptr<DepthAveragedSolver>  solver;
      dealii::TimerOutput                  *timer = nullptr;
      io::ParticleOutput                    particle_output;
      io::GridOutput                        grid_output;
      bool                                  write_grid             = true;
      unsigned int                          check_interval         = 10;
      bool                                  write_table            = false;
      bool                                  check_conservation     = false;
      double                                conservation_tolerance = 0.;
      std::array<double, 2>                 conservation{{0., 0.}};
      double                                max_conservation_error = 0.;
      /** 'Symmetry line' (NaN: off) and the largest asymmetry so far. */
      double symmetry_line      = std::numeric_limits<double>::quiet_NaN();
      double symmetry_tolerance = 1e-9, max_asymmetry = 0.;

      ExactSolution exact_solution = ExactSolution::none;
      double        dam_position = 0., left_depth = 1., right_depth = 0.;
      /** 'Slope angle' [rad] of the dam break on a slope and of the sliding block. */
      double slope_angle = 0.;
      double tolerance   = 0.;
      /** The release's surface h + Z (for the still state). */
      std::unique_ptr<dealii::FunctionParser<2>> surface;

      /** Energy at the start: kinetic + potential (the guard's budget). */
      double initial_energy = 0., total_mass = 0., initial_max_depth = 0.;
      /** The release's centre of mass (runout and travel angle of the maps). */
      dealii::Point<2> release_centre;
      /** 'Hazard maps' (allocated only when enabled). */
      bool                        write_maps    = false;
      double                      map_threshold = 0.05;
      unsigned int                map_interval  = 5;
      std::unique_ptr<HazardMaps> maps;
      double                      max_error = 0.;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
