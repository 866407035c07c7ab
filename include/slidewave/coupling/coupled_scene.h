#ifndef slidewave_coupling_coupled_scene_h
#define slidewave_coupling_coupled_scene_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <memory>
#include <optional>
#include <slidewave/core/scene_parameters.h>
#include <slidewave/core/statistics.h>
#include <slidewave/coupling/soil_water_interface.h>
#include <slidewave/mpm/material_point_solver.h>
#include <slidewave/mpm/particle_output.h>
#include <slidewave/water/shallow_water_1d.h>
#include <slidewave/water/water_output.h>
#include <slidewave/water/water_state_parameters.h>
#include <string>

namespace slidewave
{
  namespace coupling
  {
    /** Where the water cells come from (subsection "Coupling", 'Water cells'). */
    enum class WaterCells
    {
      grid_columns, ///< the columns of the material points' grid at set-up
      water_mesh    ///< subsection "Shallow water/Mesh"; the bed is interpolated onto it
    };

    /** Subsection "Coupling". */
    struct CouplingParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      void
      parse_parameters(dealii::ParameterHandler &prm);

      double       water_density    = 1000.;
      WaterCells   water_cells      = WaterCells::grid_columns;
      SoilSurface  soil_surface     = SoilSurface::envelope;
      bool         loads_on_soil    = true;
      unsigned int maximum_substeps = 1;

      /** Verification: if > 0, the run fails (exit status 3) beyond these. */
      double tolerance_volume       = 0.;
      double tolerance_free_surface = 0.;
      double tolerance_soil_speed   = 0.;
    };



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
    class CoupledScene
    {
    public:
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      CoupledScene(const SceneParameters &scene, dealii::ParameterHandler &prm);

      /** Runs the scene; throws RunFailure when the state becomes invalid. */
      bool
      run();

    private:
      bool
      run_time_loop(dealii::TimerOutput &timer);

      /** Builds the water on the soil just created (inside the soil's set-up). */
      void
      setup_water();

      /** The water at the initial condition over the current bed. */
      void
      set_initial_water();

      /** Soil surface to bed, bed to water. */
      void
      exchange_bed();

      /** The run-time guards of both solvers; throws RunFailure. */
      void
      check_state(unsigned int step, double time, bool check_soil) const;

      void
      add_statistics(Statistics  &statistics,
                     unsigned int step,
                     double       time,
                     double       dt,
                     unsigned int soil_steps,
                     unsigned int water_steps) const;

      void
      write_output(unsigned int index, double time);

      /** Largest |eta - still level| over the wet cells. */
      double
      free_surface_deviation() const;

      const SceneParameters          &scene;
      CouplingParameters              coupling;
      mpm::MaterialPointParameters    soil_parameters;
      water::SolverParameters         water_parameters;
      std::optional<water::WaterMesh> configured_mesh;
      water::WaterBoundary            boundaries[2];
      water::BedElevation             terrain;
      water::InitialCondition         initial_condition;
      std::string                     gauge_text;
      unsigned int                    check_interval = 10;

      std::unique_ptr<mpm::MaterialPointSolver> soil;
      std::unique_ptr<water::ShallowWater1D>    water;
      std::unique_ptr<SoilWaterInterface>       interface;
      water::GaugeRecorder                      gauges;
      mpm::ParticleOutput                       particle_output;

      double initial_volume = 0., initial_toe = 0.;
    };
  } // namespace coupling
} // namespace slidewave

#endif
