#include <algorithm>
#include <cmath>
#include <slidewave/core/input_error.h>
#include <slidewave/granular/drag_law.h>

namespace slidewave
{
  namespace granular
  {
    namespace
    {
      void
      require_positive_property(const char *name, const double value, const char *unit)
      {
        if (!(value > 0.) || !std::isfinite(value))
          throw InputError(name,
                           to_string(value),
                           std::string("a finite number > 0 (") + unit + ")");
      }
    } // namespace



    DragLaw::DragLaw(const double fluid_density,
                     const double fluid_viscosity,
                     const double grain_diameter_d50)
      : density(fluid_density)
      , viscosity(fluid_viscosity)
      , d50(grain_diameter_d50)
    {
      require_positive_property("fluid density", fluid_density, "kg/m^3");
      require_positive_property("fluid dynamic viscosity", fluid_viscosity, "Pa s");
      require_positive_property("grain diameter D50", grain_diameter_d50, "m");
    }



    double
    DragLaw::capped_porosity(const double porosity)
    {
      if (!(porosity > 0.) || !(porosity <= 1.))
        throw InputError("porosity",
                         to_string(porosity),
                         "0 < n <= 1 (the drag law caps n at 0.99; n <= 0 means no pores, "
                         "n > 1 is not a volume fraction)");
      return std::min(porosity, porosity_cap);
    }



    double
    DragLaw::permeability(const double porosity) const
    {
      const double n = capped_porosity(porosity);
      return d50 * d50 * n * n * n / (kozeny_carman_constant * (1. - n) * (1. - n));
    }



    double
    DragLaw::forchheimer_factor(const double porosity)
    {
      const double n = capped_porosity(porosity);
      return ergun_inertial_coefficient / std::sqrt(ergun_viscous_coefficient * n * n * n);
    }



    double
    DragLaw::darcy_coefficient(const double porosity, const double permeability) const
    {
      const double n = capped_porosity(porosity);
      require_positive_property("permeability", permeability, "m^2");
      return n * n * viscosity / permeability;
    }



    double
    DragLaw::drag_coefficient(const double porosity,
                              const double permeability,
                              const double relative_speed) const
    {
      if (!(relative_speed >= 0.) || !std::isfinite(relative_speed))
        throw InputError("relative speed |v^f - v^s|",
                         to_string(relative_speed),
                         "a finite number >= 0 (m/s)");
      const double n = capped_porosity(porosity);
      return darcy_coefficient(n, permeability)
             + n * n * n * density * forchheimer_factor(n) / std::sqrt(permeability)
                 * relative_speed;
    }



    template <int dim>
    dealii::Tensor<1, dim>
    DragLaw::drag_force(const double                  porosity,
                        const double                  permeability,
                        const dealii::Tensor<1, dim> &relative_velocity) const
    {
      return drag_coefficient(porosity, permeability, relative_velocity.norm()) * relative_velocity;
    }



    double
    DragLaw::particle_reynolds_number(const double relative_speed) const
    {
      return density * relative_speed * d50 / viscosity;
    }



    double
    DragLaw::fluid_density() const
    {
      return density;
    }



    double
    DragLaw::fluid_viscosity() const
    {
      return viscosity;
    }



    double
    DragLaw::grain_diameter() const
    {
      return d50;
    }



    template dealii::Tensor<1, 2>
    DragLaw::drag_force<2>(double, double, const dealii::Tensor<1, 2> &) const;
    template dealii::Tensor<1, 3>
    DragLaw::drag_force<3>(double, double, const dealii::Tensor<1, 3> &) const;
  } // namespace granular
} // namespace slidewave
