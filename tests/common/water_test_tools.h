// Helpers shared by the water unit tests: run the 1D solver on a given problem without a
// scene file.
#ifndef slidewave_tests_water_test_tools_h
#define slidewave_tests_water_test_tools_h

#include <cmath>
#include <cstdio>
#include <functional>
#include <slidewave/water/dam_break_solutions.h>
#include <slidewave/water/shallow_water_1d.h>
#include <string>
#include <vector>

namespace slidewave_tests
{
  using namespace slidewave::water;

  struct Scheme
  {
    NumericalFlux  flux;
    Reconstruction reconstruction;
    Limiter        limiter;
    TimeIntegrator integrator;

    std::string
    name() const
    {
      std::string n = flux == NumericalFlux::roe ? "roe" : "hll";
      if (reconstruction == Reconstruction::first_order)
        n += " first-order";
      else
        n += limiter == Limiter::minmod   ? " minmod" :
             limiter == Limiter::van_leer ? " van-leer" :
                                            " superbee";
      n += integrator == TimeIntegrator::forward_euler ? " euler" : " rk2";
      return n;
    }

    ShallowWaterParameters
    parameters(const double courant_fraction = 0.9) const
    {
      ShallowWaterParameters p;
      p.flux            = flux;
      p.reconstruction  = reconstruction;
      p.limiter         = limiter;
      p.time_integrator = integrator;
      p.courant_number  = courant_fraction * p.maximum_courant_number();
      // The scheme itself, without the thin-film velocity damping (a model choice that
      // changes the solution where h < 1e-4 m, e.g. at the tip of a dry-bed dam break).
      p.film_depth = 0.;
      return p;
    }
  };

  /** Every combination of flux, reconstruction/limiter and time integrator. */
  inline std::vector<Scheme>
  all_schemes()
  {
    std::vector<Scheme> schemes;
    for (const auto flux : {NumericalFlux::roe, NumericalFlux::hll})
      for (const auto integrator : {TimeIntegrator::forward_euler, TimeIntegrator::ssp_rk2})
        {
          schemes.push_back({flux, Reconstruction::first_order, Limiter::minmod, integrator});
          for (const auto limiter : {Limiter::minmod, Limiter::van_leer, Limiter::superbee})
            schemes.push_back({flux, Reconstruction::second_order, limiter, integrator});
        }
    return schemes;
  }

  /** Advances @p water from 0 to @p end_time with its CFL time step; returns the steps. */
  inline unsigned int
  run_until(ShallowWater1D &water, const double end_time, const double max_dt = 1e300)
  {
    double       t     = 0.;
    unsigned int steps = 0;
    while (t < end_time - 1e-14)
      {
        double dt = std::min(water.stable_time_step(), max_dt);
        dt        = std::min(dt, end_time - t);
        water.advance(t, dt);
        t += dt;
        ++steps;
      }
    return steps;
  }

  /** Sets h and u from functions of x at the cell centres. */
  inline void
  set_state(ShallowWater1D                      &water,
            const std::function<double(double)> &depth,
            const std::function<double(double)> &velocity)
  {
    std::vector<double> h(water.n_cells()), hu(water.n_cells());
    for (unsigned int i = 0; i < water.n_cells(); ++i)
      {
        const double x = water.mesh().center(i);
        h[i]           = depth(x);
        hu[i]          = h[i] * velocity(x);
      }
    water.set_state(h, hu);
  }

  /** L1 depth error against a dam-break solution at time @p t. */
  inline double
  l1_depth_error(const ShallowWater1D &water, const DamBreakSolution &exact, const double t)
  {
    double error = 0.;
    for (unsigned int i = 0; i < water.n_cells(); ++i)
      {
        double h, u;
        exact.evaluate(water.mesh().center(i), t, h, u);
        error += std::abs(water.depth()[i] - h) * water.mesh().width(i);
      }
    return error;
  }

  inline const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "no";
  }
} // namespace slidewave_tests

#endif
