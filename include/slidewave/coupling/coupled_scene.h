#ifndef slidewave_coupling_coupled_scene_h
#define slidewave_coupling_coupled_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <slidewave/core/memory_estimate.h>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/core/time_stepped_scene.h>
#include <slidewave/coupling/coupling_parameters.h>
#include <slidewave/coupling/soil_water_interface.h>
#include <slidewave/io/particle_output.h>
#include <slidewave/soil/material_point_solver.h>
#include <slidewave/water/shallow_water_1d.h>
#include <slidewave/water/water_output.h>
#include <slidewave/water/water_state_parameters.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace coupling
  {
    /**
     * Landslide-generated waves (Physics = coupled; paper 000, Algorithm 1): the soil as
     * material points ("Material points") under the 1D shallow water ("Shallow water"),
     * coupled through the seabed (SoilWaterInterface). One coupled step:
     *
     *   1. the soil advances with the water loads of the last step (Eqs. 13–23);
     *   2. the bed is rebuilt from the soil surface; the water keeps its depth (volume);
     *   3. the water advances over the new bed (Eqs. 24–37);
     *   4. the water's pressure and bed shear become point forces on the surface points.
     *
     * The step is the smaller of the two stable steps (Eq. 38). With 'Maximum substeps'
     * N > 1 the solver with the smaller stable step takes up to N steps inside one step of
     * the other (the exchange happens once per coupled step).
     */
    class CoupledScene : public TimeSteppedScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      CoupledScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** What the scene needs in memory, from its counts, before it allocates them. */
      core::MemoryEstimate
      memory_estimate() const;

      /** Runs the scene; throws RunFailure when the state becomes invalid. */
      bool
      run();

      /** @name The scene's part of the time loop (TimeSteppedScene) */
      /** @{ */
      std::string
      timer_prefix() const override
      {
        return "coupled";
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

      /** Eq. 38, or the larger step with the other solver sub-cycling inside it. */
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

      /** The soil's grid and materials and the water cells. */
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
      /** @} */

    private:
      /** The soil, with the timer of the run. */
      void
      create_soil(dealii::TimerOutput &timer);

      /** Builds the water on the soil's points just created and loads them (between the
       *  soil's create_points() and initialize_stress(), so that the initial stress
       *  carries the water's loads). */
      void
      setup_water();

      /** The soil's local points, for the interface to write their point forces (the
       *  soil's layout declares these as loads set from outside). */
      particles::PointCloud &
      soil_points()
      {
        return soil->points();
      }

      /** The water on @p mesh and the interface with the soil @p columns (interfaces). */
      void
      build_water(const water::WaterMesh &mesh, const std::vector<double> &columns);

      /** The water at the initial condition over the current bed. */
      void
      set_initial_water();

      /** Soil surface to bed, bed to water. */
      void
      exchange_bed();

      /** The run-time guards of both solvers; throws RunFailure. */
      void
      check_state(unsigned int step, double time, bool check_soil) const;

      /** Largest |eta - still level| over the wet cells. */
      double
      free_surface_deviation() const;

      const SceneParameters          &scene;
      CouplingParameters              coupling;
      soil::MaterialPointParameters   soil_parameters;
      water::ShallowWaterParameters   water_parameters;
      std::optional<water::WaterMesh> configured_mesh;
      water::WaterBoundary            boundaries[2];
      water::BedElevation             terrain;
      water::InitialCondition         initial_condition;
      std::string                     gauge_text;
      unsigned int                    check_interval = 10;

      /** The soil's background grid (declared before the soil: it outlives it). */
      std::unique_ptr<grid::BackgroundGrid>      grid;
      std::unique_ptr<soil::MaterialPointSolver> soil;
      std::unique_ptr<water::ShallowWater1D>     water;
      std::unique_ptr<SoilWaterInterface>        interface;
      water::GaugeRecorder                       gauges;
      io::ParticleOutput                         particle_output;

      double initial_volume = 0., initial_toe = 0.;
      /** The soil columns of the interface (their x interfaces). */
      std::vector<double> columns;
      /** The stable steps of the soil and the water at the start of the step. */
      double dt_soil = 0., dt_water = 0.;
      /** Steps of each solver in the last coupled step, and the water's last step. */
      unsigned int n_soil = 0, n_water = 0;
      double       last_water_step = 0.;
      /** Running maxima of the verification. */
      double max_volume_balance = 0., max_deviation = 0., max_soil_speed = 0.;

      dealii::TimerOutput *timer = nullptr;
    };
  } // namespace coupling
} // namespace slidewave

#endif
