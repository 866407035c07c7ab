#ifndef slidewave_water_dam_break_solutions_h
#define slidewave_water_dam_break_solutions_h

namespace slidewave
{
  namespace water
  {
    /**
     * Exact solution of the dam break on a flat frictionless bed: depth h_l left of x0,
     * h_r right of it, at rest at t = 0 (../shared/VERIFICATION.md).
     *
     * h_r > 0 is Stoker's wet-bed solution (rarefaction, plateau h_m, u_m, shock at speed
     * S; paper 000 §4.2); h_r = 0 is Ritter's dry-bed solution (rarefaction reaching the
     * front at x0 + 2 sqrt(g h_l) t).
     */
    class DamBreakSolution
    {
    public:
      DamBreakSolution(double left_depth, double right_depth, double dam_position, double gravity);

      /** Depth and velocity at (@p x, @p t). */
      void
      evaluate(double x, double t, double &depth, double &velocity) const;

      /** Plateau depth h_m (Stoker) or 0 (Ritter). */
      double
      middle_depth() const
      {
        return h_m;
      }

      /** Plateau velocity u_m (Stoker); the front speed 2 sqrt(g h_l) (Ritter). */
      double
      middle_velocity() const
      {
        return u_m;
      }

      /** Shock speed S (Stoker); the front speed (Ritter). */
      double
      shock_speed() const
      {
        return s;
      }

    private:
      double h_l, h_r, x0, g;
      double h_m, u_m, s;
    };



    /**
     * Thacker's planar free surface oscillating in a parabolic bowl B = D0 x^2 / L^2
     * (../shared/VERIFICATION.md): smooth, with two moving shorelines.
     */
    class ThackerSolution
    {
    public:
      ThackerSolution(double d0, double half_width, double amplitude, double gravity);

      void
      evaluate(double x, double t, double &depth, double &velocity) const;

      double
      angular_frequency() const
      {
        return omega;
      }

    private:
      double d0, l, a, omega;
    };
  } // namespace water
} // namespace slidewave

#endif
