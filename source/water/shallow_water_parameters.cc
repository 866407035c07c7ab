#include <slidewave/core/input_error.h>
#include <slidewave/water/shallow_water_parameters.h>

namespace slidewave
{
  namespace water
  {
    void
    ShallowWaterParameters::declare_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.declare_entry("Gravity", "9.81", Double(), "Gravitational acceleration g [m/s^2].");
      prm.declare_entry("Dry depth",
                        "1e-8",
                        Double(),
                        "Depth [m] at or below which a cell counts as dry: its velocity is "
                        "zero and it carries no discharge. Its water is kept (volume is "
                        "conserved).");
      prm.declare_entry("Film depth",
                        "1e-4",
                        Double(),
                        "Depth [m] below which the velocity of a thin film is damped "
                        "smoothly to zero (u = 2 h hu / (h^2 + h_film^2)), so that films "
                        "left by a receding shoreline get no spurious speed; 0 switches the "
                        "damping off.");
      prm.declare_entry("Courant number",
                        "0.5",
                        Double(),
                        "C in dt = C min_i dx_i / (|u_i| + sqrt(g h_i)) (paper 000, Eq. 37). "
                        "At most 1 for first order, 0.5 for second order.");
      prm.declare_entry("Manning coefficient",
                        "0",
                        Double(),
                        "Manning's n [s/m^(1/3)] of the bed friction (paper 000, Eq. 8); 0 "
                        "switches friction off.");
      prm.declare_entry("Numerical flux",
                        "roe",
                        Selection("roe|hll"),
                        "'roe': Roe's approximate Riemann solver with the Harten-Hyman "
                        "entropy fix (paper 000, Eqs. 30-32), HLL at wet/dry interfaces. "
                        "'hll': HLL with Einfeldt's wave speeds, cheaper and more diffusive.");
      prm.declare_entry("Reconstruction",
                        "second order",
                        Selection("first order|second order"),
                        "'first order': piecewise constant. 'second order': MUSCL, limited "
                        "linear reconstruction of depth, free surface and velocity.");
      prm.declare_entry("Limiter",
                        "minmod",
                        Selection("minmod|van leer|superbee"),
                        "Slope limiter of the second-order reconstruction, from the most "
                        "diffusive (minmod) to the most compressive (superbee).");
      prm.declare_entry("Time integrator",
                        "ssp rk2",
                        Selection("forward euler|ssp rk2"),
                        "'forward euler': one stage (paper 000, Eq. 28); with second-order "
                        "reconstruction the face values get a half-step Hancock predictor "
                        "(MUSCL-Hancock), second order in time at one flux evaluation per "
                        "step. 'ssp rk2': Heun's strong-stability-preserving two-stage method.");
    }



    void
    ShallowWaterParameters::parse_parameters(dealii::ParameterHandler &prm, const std::string &path)
    {
      gravity             = prm.get_double("Gravity");
      dry_depth           = prm.get_double("Dry depth");
      film_depth          = prm.get_double("Film depth");
      courant_number      = prm.get_double("Courant number");
      manning_coefficient = prm.get_double("Manning coefficient");
      flux           = prm.get("Numerical flux") == "roe" ? NumericalFlux::roe : NumericalFlux::hll;
      reconstruction = prm.get("Reconstruction") == "first order" ? Reconstruction::first_order :
                                                                    Reconstruction::second_order;
      const std::string limiter_name = prm.get("Limiter");
      limiter                        = limiter_name == "minmod"   ? Limiter::minmod :
                                       limiter_name == "van leer" ? Limiter::van_leer :
                                                                    Limiter::superbee;
      time_integrator                = prm.get("Time integrator") == "forward euler" ?
                                         TimeIntegrator::forward_euler :
                                         TimeIntegrator::ssp_rk2;

      require_positive(path + "/Gravity", gravity);
      require_positive(path + "/Dry depth", dry_depth);
      require_non_negative(path + "/Film depth", film_depth);
      require_non_negative(path + "/Manning coefficient", manning_coefficient);
      const double limit = maximum_courant_number();
      if (!(courant_number > 0.) || !(courant_number <= limit))
        throw InputError(path + "/Courant number",
                         to_string(courant_number),
                         "a number in (0, " + to_string(limit)
                           + "]: the stability limit of "
                             "the "
                           + (reconstruction == Reconstruction::first_order ? "first" : "second")
                           + "-order scheme");
    }



    double
    ShallowWaterParameters::maximum_courant_number() const
    {
      return reconstruction == Reconstruction::first_order ? 1. : 0.5;
    }
  } // namespace water
} // namespace slidewave
