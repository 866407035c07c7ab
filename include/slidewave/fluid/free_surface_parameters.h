#ifndef slidewave_fluid_free_surface_parameters_h
#define slidewave_fluid_free_surface_parameters_h

#include <array>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <slidewave/fluid/flow_boundaries.h>
#include <slidewave/grid/background_grid.h>
#include <slidewave/grid/rigid_solid.h>
#include <string>
#include <vector>

namespace slidewave
{
  namespace fluid
  {
    /** The value at @p p of the expression of x and y @p expression; a malformed one is
     *  an InputError naming @p parameter. */
    double
    evaluate_xy(const std::string      &parameter,
                const std::string      &expression,
                const dealii::Point<2> &p);

    /** The interface equation of the phase field (paper 002, Appendix B). */
    enum class PhaseFieldModel
    {
      conservative_allen_cahn, ///< Chiu and Lin (2011): the sharpening in divergence form
      allen_cahn               ///< paper 002, Eq. 91: the double-well reaction term
    };

    /** The verification a scene runs against an exact solution. */
    enum class FlowExactSolution
    {
      none,
      hydrostatic,   ///< water at rest: p = rho_w g (eta - y), u = 0
      poiseuille,    ///< channel between no-slip bottom and top, driven by gravity along x
      martin_moyce,  ///< collapse of a column of width a, height 2a: front against experiment
      standing_wave, ///< first sloshing mode of the tank: period against linear theory
      darcy,         ///< uniform flow through a porous medium driven by gravity along x
      taylor_green   ///< decaying vortices in a closed square with free-slip sides
    };

    /** The two fluids and how density and viscosity go across the interface (paper 002,
     *  Eqs. 89-90: linear in the phase field phi clipped to [0, 1]). */
    struct FluidProperties
    {
      double               water_density = 1000., air_density = 1.2;
      double               water_viscosity = 1e-3, air_viscosity = 1.8e-5;
      dealii::Tensor<1, 2> gravity;

      double
      density(const double phi) const
      {
        const double c = phi < 0. ? 0. : phi > 1. ? 1. : phi;
        return air_density + (water_density - air_density) * c;
      }

      double
      viscosity(const double phi) const
      {
        const double c = phi < 0. ? 0. : phi > 1. ? 1. : phi;
        return air_viscosity + (water_viscosity - air_viscosity) * c;
      }
    };

    /** A rectangle of water at the start: [x0, x1] x [y0, y1]. */
    struct WaterBox
    {
      dealii::Point<2> lower, upper;
    };

    /**
     * Everything of subsection "Free surface flow": the grid, the fluids, the sides, the
     * water at the start, the phase field, the time scheme, the linear solver, the guards,
     * gauges and the verification (doc/free-surface-flow.md).
     */
    struct FreeSurfaceParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks the entries (the handler inside "Free surface flow"). */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /** The grid's changes (adaptivity, balance) as grid::BackgroundGrid takes them. */
      grid::GridChanges
      grid_changes() const;

      /** The interface thickness epsilon [m]. */
      double
      interface_thickness() const
      {
        return thickness_in_cells * cell_size;
      }

      dealii::Point<2> lower_left, upper_right;
      double           cell_size       = 0.01;
      bool             adaptive        = false;
      unsigned int     adaptive_levels = 2, buffer_cells = 2, adaptivity_interval = 10;
      double           refinement_threshold = 0.01;
      double           imbalance_threshold  = 1.1;
      unsigned int     balance_interval     = 50;

      FluidProperties fluid;
      /** Left, right, bottom, top (the grid's boundary ids 0..3), the inflow and the
       *  backflow stabilization. */
      FlowBoundaries boundaries;

      /** The water surface y = eta(x) (empty: none) and rectangles of water. */
      std::string           surface_elevation;
      std::vector<WaterBox> water_boxes;
      /** The velocity at the start, "u_x; u_y" of x and y. */
      std::string initial_velocity = "0; 0";

      /** Rigid solids in the flow (permanent): the velocity is held at zero at every
       *  velocity node inside them or on their edges. Not read from this section:
       *  granular water gives the skeleton's solids. */
      std::vector<grid::RigidSolid> solids;

      /** A fixed porous structure: porosity n(x, y) and permeability kappa(x, y) [m^2]
       *  (empty porosity: none). */
      std::string porosity, permeability = "1e-8";

      PhaseFieldModel phase_field_model  = PhaseFieldModel::conservative_allen_cahn;
      double          thickness_in_cells = 1.;
      double          mobility_factor    = 1.;

      /** Of the velocity and the pressure (Q1-Q1 or Q2-Q2); the phase field is Q1. */
      unsigned int element_degree    = 1;
      double       theta             = 0.5;
      double       courant_number    = 0.5;
      double       maximum_time_step = 0.01;
      bool         grad_div          = true;
      /** The subscales of SUPG and PSPG: false, quasi-static (tau_m with the step);
       *  true, dynamic (they are integrated in time at the quadrature points). */
      bool         dynamic_subscales       = false;
      std::string  preconditioner          = "ilu";
      double       linear_tolerance        = 1e-8;
      unsigned int max_iterations          = 1000;
      unsigned int preconditioner_interval = 10;

      double              max_volume_drift = 0.05;
      double              max_speed        = 1e3;
      std::vector<double> gauges;
      /** Points where the water's pressure is written every step (pressure probes). */
      std::vector<dealii::Point<2>> pressure_probes;
      bool                          write_surface = true;

      FlowExactSolution exact_solution = FlowExactSolution::none;
      double            tolerance      = 0.;
    };
  } // namespace fluid
} // namespace slidewave

#endif
