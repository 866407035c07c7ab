#include <cmath>
#include <slidewave/water/dam_break_solutions.h>

namespace slidewave
{
  namespace water
  {
    DamBreakSolution::DamBreakSolution(const double left_depth,
                                       const double right_depth,
                                       const double dam_position,
                                       const double gravity)
      : h_l(left_depth)
      , h_r(right_depth)
      , x0(dam_position)
      , g(gravity)
    {
      const double c_l = std::sqrt(g * h_l);
      if (h_r <= 0.)
        {
          h_m = 0.;
          u_m = 2. * c_l;
          s   = 2. * c_l;
          return;
        }
      // Middle depth: root of the rarefaction-shock matching condition, monotone on
      // (h_r, h_l); bisection to round-off.
      const auto f = [&](const double hm) {
        return 2. * (c_l - std::sqrt(g * hm))
               - (hm - h_r) * std::sqrt(0.5 * g * (hm + h_r) / (hm * h_r));
      };
      double a = h_r, b = h_l;
      for (unsigned int k = 0; k < 200 && b - a > 1e-16 * h_l; ++k)
        {
          const double m = 0.5 * (a + b);
          if (f(m) > 0.)
            a = m;
          else
            b = m;
        }
      h_m = 0.5 * (a + b);
      u_m = 2. * (c_l - std::sqrt(g * h_m));
      s   = h_m * u_m / (h_m - h_r);
    }



    void
    DamBreakSolution::evaluate(const double x,
                               const double t,
                               double      &depth,
                               double      &velocity) const
    {
      const double c_l = std::sqrt(g * h_l);
      if (t <= 0.)
        {
          depth    = x <= x0 ? h_l : h_r;
          velocity = 0.;
          return;
        }
      const double xi = (x - x0) / t;
      if (xi <= -c_l)
        {
          depth    = h_l;
          velocity = 0.;
          return;
        }
      // End of the rarefaction fan: u_m - c_m (Stoker) or the dry front 2 c_l (Ritter).
      const double fan_end = h_r > 0. ? u_m - std::sqrt(g * h_m) : 2. * c_l;
      if (xi <= fan_end)
        {
          depth    = (2. * c_l - xi) * (2. * c_l - xi) / (9. * g);
          velocity = 2. / 3. * (c_l + xi);
          return;
        }
      if (h_r > 0. && xi <= s)
        {
          depth    = h_m;
          velocity = u_m;
          return;
        }
      depth    = h_r;
      velocity = 0.;
    }



    ThackerSolution::ThackerSolution(const double d0,
                                     const double half_width,
                                     const double amplitude,
                                     const double gravity)
      : d0(d0)
      , l(half_width)
      , a(amplitude)
      , omega(std::sqrt(2. * gravity * d0) / half_width)
    {
    }



    void
    ThackerSolution::evaluate(const double x, const double t, double &depth, double &velocity) const
    {
      const double shift = a * std::cos(omega * t);
      const double r     = (x - shift) / l;
      depth              = std::max(0., d0 * (1. - r * r));
      velocity           = depth > 0. ? -a * omega * std::sin(omega * t) : 0.;
    }
  } // namespace water
} // namespace slidewave
