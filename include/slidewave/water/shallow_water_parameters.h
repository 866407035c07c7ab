#ifndef slidewave_water_shallow_water_parameters_h
#define slidewave_water_shallow_water_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace slidewave
{
  namespace water
  {
    enum class NumericalFlux
    {
      roe,
      hll
    };

    enum class Reconstruction
    {
      first_order,
      second_order
    };

    enum class Limiter
    {
      minmod,
      van_leer,
      superbee
    };

    enum class TimeIntegrator
    {
      forward_euler,
      ssp_rk2
    };

    /**
     * The numerical scheme of the water column: flux, order, limiter, time integrator,
     * Courant number, Manning coefficient, gravity and the depth below which a cell is dry.
     */
    struct ShallowWaterParameters
    {
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads and checks; @p path is the subsection path used in error messages. */
      void
      parse_parameters(dealii::ParameterHandler &prm, const std::string &path);

      /**
       * The largest Courant number at which the chosen scheme is stable and keeps depths
       * non-negative: 1 for first order (Godunov-type schemes with the hydrostatic
       * reconstruction), 1/2 for the MUSCL reconstruction (its face values must stay within
       * the range of the neighbours over one step).
       */
      double
      maximum_courant_number() const;

      double         gravity             = 9.81;
      double         dry_depth           = 1e-8;
      double         film_depth          = 1e-4;
      double         courant_number      = 0.5;
      double         manning_coefficient = 0.;
      NumericalFlux  flux                = NumericalFlux::roe;
      Reconstruction reconstruction      = Reconstruction::second_order;
      Limiter        limiter             = Limiter::minmod;
      TimeIntegrator time_integrator     = TimeIntegrator::ssp_rk2;
    };
  } // namespace water
} // namespace slidewave

#endif
