#ifndef slidewave_granular_granular_water_parameters_h
#define slidewave_granular_granular_water_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace granular
  {
    /** How a point's intrinsic permeability follows its porosity. */
    enum class PermeabilityLaw
    {
      constant,     ///< the given k whatever the porosity
      kozeny_carman ///< k(n) = D50^2 n^3 / (180 (1 - n)^2) (paper 002, Eq. 4; DragLaw)
    };

    /** The exact solutions a granular-water scene can be checked against. */
    enum class GranularExactSolution
    {
      none,
      terzaghi, ///< one-dimensional consolidation under a top load (paper 002, §4.1)
      at_rest,  ///< a saturated column settled under gravity: hydrostatic and geostatic
      seepage,  ///< steady flow down through a layer at rest: Darcy-Forchheimer's gradient
      settling  ///< a uniform suspension settling in a closed column: its fall and its bed
    };

    /**
     * What couples the granular skeleton ("Material points") with the water ("Free
     * surface flow") in a scene of Physics = granular water (subsection "Granular
     * water"; paper 002, §2.1 and §3.5).
     */
    struct GranularWaterParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks the subsection (entered by the caller, named @p path in
       *  messages). */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /** rho^s, the grains' density [kg/m^3]; the materials' 'Density' is the dry
       *  density (1 - n_0) rho^s, which sets the initial porosity n_0. */
      double          grain_density    = 2650.;
      PermeabilityLaw permeability_law = PermeabilityLaw::constant;
      /** k [m^2] of the constant law. */
      double permeability = 1e-10;
      /** D50 [m] of Kozeny–Carman (and the DragLaw's Reynolds number). */
      double d50 = 1e-3;
      /** The drag's Forchheimer term (Eq. 3) on top of Darcy's. */
      bool forchheimer = true;
      /** The skeleton's drag and pressure of the new step implicit at its nodes, its
       *  momentum eliminated from the water's equations (fluid::PorousMedium); false:
       *  explicit (the water sees the skeleton's old velocity). */
      bool implicit_drag = true;
      /** The grains take the projection of the increment the water's elimination assumed
       *  (DragProjection, 'semi-implicit projected'; implies implicit_drag); false: the
       *  lumped nodal drag W_I ('semi-implicit') or the explicit coupling. */
      bool projected_drag = true;
      /** The grains' nodal momentum solved with the water (fluid::NodalGrainsCoupling,
       *  'semi-implicit consistent'; implies implicit_drag). */
      bool consistent_drag = false;
      /** n_s: where a cell's points together are looser, their grains are out of
       *  contact, a suspension without effective stress or stiffness
       *  (soil::SoilModel::update_cell). */
      double suspension_porosity = 0.6;
      /** A pressure [Pa] on the top row of points (Terzaghi's load; 0: none). */
      double top_load = 0.;
      /** Several skeleton steps inside one water step (the water's step limited by its
       *  Courant number and the coupling, the skeleton's by its P-wave). */
      bool sub_cycling = false;

      GranularExactSolution exact_solution = GranularExactSolution::none;
      /** The height of the consolidating column [m] (its base at the grid's bottom). */
      double column_height = 1.;
      /** The time factors T_v at which the pore pressure profile is compared. */
      std::vector<double> time_factors{0.05, 0.1, 0.2, 0.5, 1.};
      /** If > 0, the run fails (exit status 3) when the error exceeds it. */
      double tolerance = 0.;
    };
  } // namespace granular
} // namespace slidewave

#endif
