#ifndef slidewave_depth_averaged_bingham_h
#define slidewave_depth_averaged_bingham_h

#include <algorithm>
#include <cmath>
#include <limits>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * The depth-integrated Bingham rheology of paper 001, §2.2 (Eqs. 3–9), as inline
     * functions of one column's state: its in-plane rate of deformation D (Eq. 4), its
     * depth-averaged velocity v and its depth h.
     */
    namespace bingham
    {
      /**
       * zeta = tau_Y / tau_B, the plug's share of the bed shear stress: the root in [0, 1]
       * of Eq. 9, 48 zeta^2 - (114 + 32 a) zeta + 65 = 0 with a = 6 mu |v| / (tau_Y h)
       * (the best quadratic fit of the cubic Eq. 8, error at most 1/32). Both roots are
       * positive (product 65/48); the smaller one lies in (0, 0.952]. It is evaluated as
       * 2c / (b + sqrt(b^2 - 4 ac)) multiplied through by tau_Y h, so that no limit
       * divides by zero and nothing cancels:
       * zeta = 130 s / (b' + sqrt(b'^2 - 12480 s^2)), s = tau_Y h, b' = 114 s + 32 (6 mu |v|).
       * Limits: tau_Y h -> 0 (no yield stress, or a dry column) gives zeta -> 0 (a purely
       * viscous profile); mu |v| -> 0 gives zeta -> 0.951 (a plug over the whole depth);
       * both zero at once: zeta = 0 (the value does not matter then: v = 0 or h = 0).
       */
      inline double
      plug_ratio(const double viscosity,
                 const double yield_stress,
                 const double speed,
                 const double depth)
      {
        const double s = yield_stress * std::max(depth, 0.);
        const double b = 114. * s + 192. * viscosity * speed;
        if (!(b > 0.))
          return 0.;
        // b >= 114 s, so b^2 - 12480 s^2 >= 516 s^2 >= 0.
        return 130. * s / (b + std::sqrt(b * b - 12480. * s * s));
      }

      /** The in-plane Bingham stress (Eq. 3) of one column [Pa]. */
      struct Stress
      {
        double xx, yy, xy;
      };

      /**
       * sigma = (2 mu + tau_Y f(I_2)) D (Eq. 3), D the in-plane rate of deformation (Eq. 4),
       * I_2 = 1/2 Dbar : Dbar the second invariant of the 3D rate (Eq. 5) with the vertical
       * shear d_z v = 3 / (2 + zeta) v / h (Eq. 6) and Dbar_33 = -(D_11 + D_22).
       *
       * Eq. 3 prints tau_Y / I_2; its units (Pa s^2 for a viscosity) show that the square
       * root is meant: f = 1 / sqrt(I_2), Bingham's law with |sigma| = 2 mu |D| + tau_Y
       * once yielded. That law's stress at rest is undetermined (any |sigma| <= tau_Y): in
       * an explicit step, round-off velocities of 1e-16 m/s give the full yield stress in a
       * random direction and set still material moving (doc/depth-averaged.md). With a
       * @p regularization time m > 0 the yield part is Papanastasiou's,
       * f = (1 - exp(-m sqrt(I_2))) / sqrt(I_2), which equals the plain law for
       * m sqrt(I_2) >> 1 and tends to m (a finite viscosity tau_Y m) at rest; m = 0 is the
       * plain law. Limits without a division by zero: I_2 = 0 gives sigma = 0;
       * |D| / sqrt(I_2) <= sqrt(2), so the yield part stays bounded by sqrt(2) tau_Y however
       * small the rate; h -> 0 makes d_z v and I_2 large, leaving the viscous part 2 mu D;
       * mu = 0 or tau_Y = 0 drop their own part.
       */
      inline Stress
      stress(const double dxx,
             const double dyy,
             const double dxy,
             const double vx,
             const double vy,
             const double depth,
             const double viscosity,
             const double yield_stress,
             const double regularization)
      {
        const double speed = std::sqrt(vx * vx + vy * vy);
        const double zeta  = plug_ratio(viscosity, yield_stress, speed, depth);
        // Half of d_z u and d_z v, the 13 and 23 entries of Dbar; a moving column of no
        // depth has an infinite vertical shear (the limit h -> 0), which leaves the
        // viscous part only.
        const double dzz = -(dxx + dyy);
        double       I2  = 0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) + dxy * dxy;
        if (depth > 0.)
          {
            const double shear = 1.5 / ((2. + zeta) * depth);
            I2 += shear * shear * speed * speed;
          }
        else if (speed > 0.)
          I2 = std::numeric_limits<double>::infinity();
        const double rate = std::sqrt(I2);
        double       f    = 0.;
        if (regularization > 0.)
          f = rate > 0. ? -std::expm1(-regularization * rate) / rate : regularization;
        else if (rate > 0.)
          f = 1. / rate;
        const double eta = 2. * viscosity + yield_stress * f;
        return {eta * dxx, eta * dyy, eta * dxy};
      }
    } // namespace bingham
  }   // namespace depth_averaged
} // namespace slidewave

#endif
