#ifndef slidewave_coupling_coupling_parameters_h
#define slidewave_coupling_coupling_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <slidewave/coupling/soil_water_interface.h>

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

      double        water_density    = 1000.;
      WaterCells    water_cells      = WaterCells::grid_columns;
      SoilSurface   soil_surface     = SoilSurface::envelope;
      bool          loads_on_soil    = true;
      WaterPressure water_pressure   = WaterPressure::hydrostatic;
      unsigned int  maximum_substeps = 1;

      /** Verification: if > 0, the run fails (exit status 3) beyond these. */
      double tolerance_volume       = 0.;
      double tolerance_free_surface = 0.;
      double tolerance_soil_speed   = 0.;
    };
  } // namespace coupling
} // namespace slidewave

#endif
