// terrain::ElevationGrid, the form every terrain source takes for the depth-averaged model
// (issue 18): elevations on a regular grid and their bilinear interpolant.
//  - A plane Z = 2 + 0.3 x - 0.7 y, sampled on 11 x 6 nodes over [0, 10] x [0, 5]
//    (dx = 1, dy = 1): value and gradient exact (the bilinear interpolant of a plane is the
//    plane) at points inside cells, on nodes, on cell faces, on the grid's far edges and
//    outside it (extrapolation by the nearest cell); checked to 1e-13 relative, round-off.
//  - A smooth bump Z = exp(-((x - 5)^2 + (y - 2.5)^2) / 2), sampled on 40 x 20, 80 x 40 and
//    160 x 80 cells: the interpolant's largest error at the cells' centres falls by 4 per
//    halving of the spacing (second order) and its gradient's, a quarter of the way into the
//    cells, by 2 (first order); checked: the last ratios within 15 % of 4 and 2.
//  - Bad grids refused: too few nodes, a value count that does not match, a non-finite
//    value (no-data must be dealt with before).
#include "unit_check.h"

#include <cmath>
#include <cstdio>
#include <deal.II/base/exceptions.h>
#include <slidewave/terrain/elevation_grid.h>
#include <vector>

using namespace slidewave;

using unit_check::check;

namespace
{

  double
  bump(const double x, const double y)
  {
    return std::exp(-((x - 5.) * (x - 5.) + (y - 2.5) * (y - 2.5)) / 2.);
  }

  /** Largest errors of the value at the cells' centres and of the gradient at the points a
   *  quarter of the way into each cell (where the gradient's error is first order: at the
   *  centre it is a central difference, second order), over every cell of a grid of
   *  2n x n cells. */
  void
  bump_errors(const unsigned int n, double &value_error, double &gradient_error)
  {
    const auto grid = terrain::ElevationGrid::from_function(
      bump, dealii::Point<2>(0., 0.), dealii::Point<2>(10., 5.), 2 * n + 1, n + 1);
    const double h = 5. / n;
    value_error = gradient_error = 0.;
    for (unsigned int i = 0; i < 2 * n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const dealii::Point<2> centre((i + 0.5) * h, (j + 0.5) * h);
          value_error
            = std::max(value_error, std::abs(grid.value(centre) - bump(centre[0], centre[1])));
          const double               x = (i + 0.25) * h, y = (j + 0.25) * h;
          const double               r = bump(x, y);
          const dealii::Tensor<1, 2> exact({-(x - 5.) * r, -(y - 2.5) * r});
          gradient_error
            = std::max(gradient_error, (grid.gradient(dealii::Point<2>(x, y)) - exact).norm());
        }
  }

  template <typename Function>
  bool
  refused(const Function &f)
  {
    try
      {
        f();
      }
    catch (const dealii::ExceptionBase &)
      {
        return true;
      }
    return false;
  }
} // namespace

int
main()
{
  dealii::deal_II_exceptions::disable_abort_on_exception();
  std::printf("a plane, 11 x 6 nodes\n");
  {
    const auto plane = [](const double x, const double y) { return 2. + 0.3 * x - 0.7 * y; };
    const auto grid  = terrain::ElevationGrid::from_function(
      plane, dealii::Point<2>(0., 0.), dealii::Point<2>(10., 5.), 11, 6);
    const std::vector<dealii::Point<2>> points      = {{0.5, 0.5},
                                                       {3.7, 2.2},
                                                       {4., 3.},
                                                       {4., 2.6},
                                                       {7.3, 1.},
                                                       {10., 5.},
                                                       {0., 0.},
                                                       {9.99, 4.999},
                                                       {-1.5, 2.},
                                                       {12., 6.5}};
    double                              value_error = 0., gradient_error = 0.;
    for (const auto &p : points)
      {
        value_error = std::max(value_error, std::abs(grid.value(p) - plane(p[0], p[1])));
        gradient_error
          = std::max(gradient_error, (grid.gradient(p) - dealii::Tensor<1, 2>({0.3, -0.7})).norm());
      }
    std::printf("  largest errors: value %.1e, gradient %.1e\n", value_error, gradient_error);
    check(value_error < 1e-13 * 10., "value exact (inside, nodes, faces, edges, outside)");
    check(gradient_error < 1e-13, "gradient exact");
    check(grid.contains(dealii::Point<2>(10., 5.)) && !grid.contains(dealii::Point<2>(-1.5, 2.)),
          "contains: the far corner yes, a point outside no");
  }

  std::printf("a bump at three resolutions\n");
  {
    double v[3], g[3];
    for (unsigned int k = 0; k < 3; ++k)
      bump_errors(20u << k, v[k], g[k]);
    for (unsigned int k = 0; k < 3; ++k)
      std::printf("  %u x %u nodes: value error %.3e, gradient error %.3e\n",
                  (40u << k) + 1,
                  (20u << k) + 1,
                  v[k],
                  g[k]);
    const double rv = v[1] / v[2], rg = g[1] / g[2];
    std::printf("  last ratios: value %.2f, gradient %.2f\n", rv, rg);
    check(std::abs(rv - 4.) < 0.6, "value second order");
    check(std::abs(rg - 2.) < 0.3, "gradient first order");
  }

  std::printf("bad grids\n");
  check(refused(
          [] { terrain::ElevationGrid(dealii::Point<2>(), 1., 1., 1, 3, std::vector<double>(3)); }),
        "one column of nodes refused");
  check(refused(
          [] { terrain::ElevationGrid(dealii::Point<2>(), 1., 1., 3, 3, std::vector<double>(8)); }),
        "8 values for 3 x 3 nodes refused");
  check(refused([] {
          std::vector<double> values(9, 1.);
          values[4] = std::nan("");
          terrain::ElevationGrid(dealii::Point<2>(), 1., 1., 3, 3, values);
        }),
        "a NaN elevation refused");

  return unit_check::finish();
}
