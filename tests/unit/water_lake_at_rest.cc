// Well-balancing: a lake at rest over a bump (../shared/VERIFICATION.md; L = 25 m,
// B = 0.2 - 0.05 (x - 10)^2 on 8 < x < 12) must stay at rest to round-off, for every flux,
// reconstruction, limiter and time integrator, on a strongly non-uniform mesh (widths
// varying by a factor of 20 in a random order), after 2000 steps:
//   - immersed bump, eta = 0.5: all cells wet;
//   - emerging bump, eta = max(B, 0.1): the top of the bump is dry, its flanks are
//     shorelines.
// The tolerance 1e-12 m (and m^2/s) is round-off for O(1) depths after thousands of
// operations: a scheme that is not well-balanced drifts by O(dx^p) ~ 1e-3 here, nine orders
// of magnitude above it. Walls at both ends: the volume must not change either (1e-12
// relative).
#include "../common/water_test_tools.h"

#include <random>

using namespace slidewave_tests;

namespace
{
  double
  bump(const double x)
  {
    return (x > 8. && x < 12.) ? 0.2 - 0.05 * (x - 10.) * (x - 10.) : 0.;
  }

  WaterMesh
  random_mesh(const unsigned int n_cells, const double length)
  {
    std::mt19937                           generator(42);
    std::uniform_real_distribution<double> factor(1., 20.);
    std::vector<double>                    widths(n_cells);
    double                                 total = 0.;
    for (auto &w : widths)
      total += (w = factor(generator));
    std::vector<double> interfaces{0.};
    for (const double w : widths)
      interfaces.push_back(interfaces.back() + w * length / total);
    interfaces.back() = length;
    return WaterMesh(interfaces);
  }
} // namespace

int
main()
{
  const WaterMesh mesh = random_mesh(200, 25.);
  std::printf("mesh: %u cells, widths from %.4f to %.4f m\n",
              mesh.n_cells(),
              mesh.min_width(),
              mesh.max_width());

  bool all_ok = true;
  for (const bool emerging : {false, true})
    {
      std::printf("%s bump:\n", emerging ? "emerging" : "immersed");
      for (const Scheme &scheme : all_schemes())
        {
          ShallowWater1D      water(mesh, scheme.parameters());
          std::vector<double> bed(mesh.n_cells()), eta0(mesh.n_cells());
          for (unsigned int i = 0; i < mesh.n_cells(); ++i)
            bed[i] = bump(mesh.center(i));
          water.set_bed(bed);
          set_state(
            water,
            [&](const double x) {
              const double eta = emerging ? std::max(bump(x), 0.1) : 0.5;
              return eta - bump(x);
            },
            [](double) { return 0.; });
          const double volume0 = water.water_volume();
          unsigned int dry     = 0;
          for (unsigned int i = 0; i < mesh.n_cells(); ++i)
            {
              eta0[i] = water.depth()[i] + bed[i];
              dry += water.depth()[i] == 0.;
            }

          double t = 0.;
          for (unsigned int step = 0; step < 2000; ++step)
            {
              const double dt = water.stable_time_step();
              water.advance(t, dt);
              t += dt;
            }

          double eta_error = 0., discharge_error = 0.;
          for (unsigned int i = 0; i < mesh.n_cells(); ++i)
            {
              eta_error       = std::max(eta_error, std::abs(water.depth()[i] + bed[i] - eta0[i]));
              discharge_error = std::max(discharge_error, std::abs(water.discharge()[i]));
            }
          const double volume_error = std::abs(water.water_volume() - volume0) / volume0;
          const bool   ok = eta_error <= 1e-12 && discharge_error <= 1e-12 && volume_error <= 1e-12;
          all_ok          = all_ok && ok;
          std::printf("  %-24s dry cells %3u  |eta - eta0| <= 1e-12: %s  |hu| <= 1e-12: %s  "
                      "volume: %s\n",
                      scheme.name().c_str(),
                      dry,
                      yes_no(eta_error <= 1e-12),
                      yes_no(discharge_error <= 1e-12),
                      yes_no(volume_error <= 1e-12));
          if (!ok)
            std::printf("    errors: eta %.3e, hu %.3e, volume %.3e\n",
                        eta_error,
                        discharge_error,
                        volume_error);
        }
    }
  std::printf("all well-balanced: %s\n", yes_no(all_ok));
  return all_ok ? 0 : 1;
}
