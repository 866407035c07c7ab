// Dam breaks against their exact solutions under refinement (../shared/VERIFICATION.md):
// Stoker (h_l = 1, h_r = 0.5, wet bed, paper 000 §4.2) and Ritter (h_l = 1, dry bed), on
// [0, 1] with the dam at 0.5, t = 0.1 (Ritter: t = 0.05, so the front stays inside),
// walls at both ends (no wave reaches them), 100 to 1600 cells.
//
// What is checked, and why:
// - Both solutions are discontinuous (shock; dry front with a kink) so no scheme converges
//   faster than first order in L1: the observed rate between 800 and 1600 cells must be at
//   least 0.6 for first order and 0.7 for the second-order schemes (measured: 0.75-0.86
//   and 0.77-1.0, superbee lowest as it steepens the smooth rarefaction into steps; a broken
//   flux, reconstruction or predictor gives ~0 or diverges: forward Euler with MUSCL but
//   without the Hancock predictor measured 0.33).
// - The second-order schemes must be more accurate than first order on the same mesh.
// - Water volume: walls, so it must not change beyond round-off (1e-13 relative).
// - Depths never negative (Ritter's dry bed).
// The errors themselves are printed to 4 significant digits; the expected output then
// catches a change of accuracy of more than about 0.1 %.
#include "../common/water_test_tools.h"

using namespace slidewave_tests;

int
main()
{
  const std::vector<unsigned int> resolutions{100, 200, 400, 800, 1600};
  const std::vector<Scheme>       schemes{
    {NumericalFlux::roe,
           Reconstruction::first_order,
           Limiter::minmod,
           TimeIntegrator::forward_euler},
    {NumericalFlux::hll,
           Reconstruction::first_order,
           Limiter::minmod,
           TimeIntegrator::forward_euler},
    {NumericalFlux::roe, Reconstruction::second_order, Limiter::minmod, TimeIntegrator::ssp_rk2},
    {NumericalFlux::roe, Reconstruction::second_order, Limiter::van_leer, TimeIntegrator::ssp_rk2},
    {NumericalFlux::roe, Reconstruction::second_order, Limiter::superbee, TimeIntegrator::ssp_rk2},
    {NumericalFlux::roe,
           Reconstruction::second_order,
           Limiter::minmod,
           TimeIntegrator::forward_euler},
    {NumericalFlux::hll,
           Reconstruction::second_order,
           Limiter::van_leer,
           TimeIntegrator::forward_euler}};

  bool all_ok = true;
  for (const double h_right : {0.5, 0.})
    {
      const double           end_time = h_right > 0. ? 0.1 : 0.05;
      const DamBreakSolution exact(1., h_right, 0.5, 9.81);
      std::printf("%s dam break, t = %.2f s: L1 depth error [m^2]\n",
                  h_right > 0. ? "Stoker" : "Ritter",
                  end_time);
      std::vector<double> first_order_errors;
      for (const Scheme &scheme : schemes)
        {
          std::printf("  %-22s", scheme.name().c_str());
          std::vector<double> errors;
          bool                positive = true, conserved = true;
          for (const unsigned int n : resolutions)
            {
              ShallowWater1D water(WaterMesh::uniform(0., 1., n), scheme.parameters());
              set_state(
                water, [&](double x) { return x < 0.5 ? 1. : h_right; }, [](double) { return 0.; });
              const double volume0 = water.water_volume();
              run_until(water, end_time);
              errors.push_back(l1_depth_error(water, exact, end_time));
              positive  = positive && water.find_invalid_cell() == water.n_cells();
              conserved = conserved && std::abs(water.water_volume() - volume0) <= 1e-13 * volume0;
              std::printf(" %.3e", errors.back());
            }
          const double rate     = std::log2(errors[errors.size() - 2] / errors.back());
          const bool   is_first = scheme.reconstruction == Reconstruction::first_order;
          const bool   rate_ok  = rate >= (is_first ? 0.6 : 0.7);
          bool         better   = true;
          if (is_first)
            first_order_errors = errors;
          else
            for (unsigned int r = 0; r < errors.size(); ++r)
              better = better && errors[r] < first_order_errors[r];
          std::printf("  rate %.2f >= %.1f: %s", rate, is_first ? 0.6 : 0.7, yes_no(rate_ok));
          if (!is_first)
            std::printf("  better than first order: %s", yes_no(better));
          std::printf("  h >= 0: %s  volume: %s\n", yes_no(positive), yes_no(conserved));
          all_ok = all_ok && rate_ok && better && positive && conserved;
        }
    }
  std::printf("all converge: %s\n", yes_no(all_ok));
  return all_ok ? 0 : 1;
}
