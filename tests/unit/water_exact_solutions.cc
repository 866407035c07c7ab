// The exact solutions the water tests compare against (../shared/VERIFICATION.md):
// Stoker's middle state for h_l = 1, h_r = 0.5 must be h_m = 0.72692045, u_m = 0.92336390,
// S = 2.95791812 (the paper's C_s = 2.9579); Ritter's depth at the dam site is 4/9 h_l at any
// time and its front moves at 2 sqrt(g h_l) = 6.264184 m/s; Thacker's period is 7.09613 s for
// D0 = 4, L = 10, g = 9.8. Printed to 8 digits: the reference values are given to 8.
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <slidewave/water/dam_break_solutions.h>

int
main()
{
  using namespace slidewave::water;
  const DamBreakSolution stoker(1., 0.5, 0.5, 9.81);
  std::printf("Stoker: h_m = %.8f  u_m = %.8f  S = %.8f\n",
              stoker.middle_depth(),
              stoker.middle_velocity(),
              stoker.shock_speed());

  double h, u;
  stoker.evaluate(0.5 + 2.95791812 * 0.1 - 1e-6, 0.1, h, u);
  std::printf("Stoker just behind the shock at t = 0.1: h = %.8f u = %.8f\n", h, u);
  stoker.evaluate(0.5 + 2.95791812 * 0.1 + 1e-6, 0.1, h, u);
  std::printf("Stoker just ahead of the shock at t = 0.1: h = %.8f u = %.8f\n", h, u);

  const DamBreakSolution ritter(1., 0., 0., 9.81);
  for (const double t : {0.1, 1., 10.})
    {
      ritter.evaluate(0., t, h, u);
      std::printf("Ritter at the dam, t = %5.1f: h = %.8f (4/9 = %.8f)\n", t, h, 4. / 9.);
    }
  std::printf("Ritter front speed = %.6f\n", ritter.shock_speed());
  ritter.evaluate(6.264184 * 1. - 1e-3, 1., h, u);
  std::printf("Ritter just behind the front at t = 1: h = %.3e\n", h);
  ritter.evaluate(6.264184 * 1. + 1e-3, 1., h, u);
  std::printf("Ritter just ahead of the front at t = 1: h = %.3e\n", h);

  const ThackerSolution thacker(4., 10., 2., 9.8);
  std::printf("Thacker: omega = %.6f  period = %.5f\n",
              thacker.angular_frequency(),
              2. * M_PI / thacker.angular_frequency());
  thacker.evaluate(2. + 10., 0., h, u);
  std::printf("Thacker shoreline at t = 0: x = 12, h = %.8f\n", h);
}
