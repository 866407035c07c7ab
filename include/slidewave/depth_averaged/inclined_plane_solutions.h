#ifndef slidewave_depth_averaged_inclined_plane_solutions_h
#define slidewave_depth_averaged_inclined_plane_solutions_h

#include <cmath>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * Exact solutions on a plane Z = -x tan(theta) descending along +x, with Coulomb
     * friction tan(phi) < tan(theta), written in the plan view of the depth-averaged model
     * (x horizontal, h the vertical thickness, u the horizontal velocity). In slope
     * coordinates (s = x / cos(theta) along the slope, T = h cos(theta) normal to it,
     * U = u / cos(theta)) they are the textbook ones:
     *
     * - a block (or a uniform slab on an infinite plane) slides at
     *   dU/dt = g (sin(theta) - cos(theta) tan(phi)) = m, that is horizontally at
     *   du/dt = m cos(theta) = g cos^2(theta) (tan(theta) - tan(phi));
     * - the dry-bed dam break of Mangeney, Heinrich and Roche (2000, Pure Appl. Geophys.
     *   157): Ritter's solution with the normal gravity g cos(theta) in the
     *   frame moving with the acceleration m: with c0 = sqrt(g cos(theta) T0) and
     *   xi = s - s0 - m t^2 / 2,
     *     T = (2 c0 - xi / t)^2 / (9 g cos(theta)),  U = 2/3 (xi / t + c0) + m t
     *   for -c0 t <= xi <= 2 c0 t, T = T0 and U = m t behind, T = 0 ahead.
     *
     * The reservoir of the dam break is infinite upslope; for a finite one the solution
     * holds downslope of where its upper end's own rarefaction reaches (the test compares
     * from the tail of the dam's rarefaction, xi >= -c0 t, onwards).
     */
    class InclinedPlaneSolutions
    {
    public:
      /** @p theta, @p phi in radians; @p h0 the vertical depth of the reservoir behind
       *  the dam at @p x0 (the block's solution needs neither). */
      InclinedPlaneSolutions(const double theta,
                             const double phi,
                             const double gravity,
                             const double h0 = 1.,
                             const double x0 = 0.)
        : cos_theta(std::cos(theta))
        , g_normal(gravity * std::cos(theta))
        , m(gravity * (std::sin(theta) - std::cos(theta) * std::tan(phi)))
        , T0(h0 * std::cos(theta))
        , c0(std::sqrt(gravity * std::cos(theta) * h0 * std::cos(theta)))
        , s0(x0 / std::cos(theta))
      {
      }

      /** The slope-parallel acceleration m = g (sin(theta) - cos(theta) tan(phi)). */
      double
      slope_acceleration() const
      {
        return m;
      }

      /** The block's horizontal acceleration m cos(theta) = g cos^2 (tan - tan). */
      double
      horizontal_acceleration() const
      {
        return m * cos_theta;
      }

      /** The dam break's vertical depth @p h and horizontal velocity @p u at (x, t). */
      void
      dam_break(const double x, const double t, double &h, double &u) const
      {
        const double xi = x / cos_theta - s0 - 0.5 * m * t * t;
        double       T = 0., U = 0.;
        if (!(t > 0.))
          {
            T = xi <= 0. ? T0 : 0.;
            U = 0.;
          }
        else if (xi <= -c0 * t)
          {
            T = T0;
            U = m * t;
          }
        else if (xi <= 2. * c0 * t)
          {
            const double a = 2. * c0 - xi / t;
            T              = a * a / (9. * g_normal);
            U              = 2. / 3. * (xi / t + c0) + m * t;
          }
        h = T / cos_theta;
        u = U * cos_theta;
      }

      /** The horizontal position of the dam break's front (the dry tip) at @p t. */
      double
      front(const double t) const
      {
        return (s0 + 2. * c0 * t + 0.5 * m * t * t) * cos_theta;
      }

      /** The horizontal position of the tail of the dam's rarefaction at @p t. */
      double
      rarefaction_tail(const double t) const
      {
        return (s0 - c0 * t + 0.5 * m * t * t) * cos_theta;
      }

    private:
      double cos_theta, g_normal, m, T0, c0, s0;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
