// The engine's quadratic B-spline shape functions (grid::bspline_weights, 'Shape functions =
// bspline': GIMP with a whole cell as the point's domain) on a hand-built uniform grid of
// 6 x 6 cells of h = 0.5 (tests/unit/patch_grid.h):
//   1. in the interior (points in cell (2, 2), 23 x 23 positions: on the faces, the cell's
//      middle, where the domain's edge meets a node) they are the tensor product of the
//      uniform quadratic B-spline centred on the nodes, both as the closed form
//      grid::bspline_1d (3/4 - s^2, (3/2 - |s|)^2 / 2) and as paper 002's Cox-de Boor
//      recursion (grid::QuadraticBSpline) on the knots a cell apart through the cells'
//      middles, whose interior function k + 1 belongs to node k; values and gradients;
//   2. partition of unity, gradients summing to zero, linear completeness of values and
//      gradients (sum S_i x_i = x_p, sum grad S_i x_i = I) there;
//   3. next to the grid's lower side (cell (2, 0), a patch without the row below), where
//      the domain pokes out of the grid: still a partition of unity with gradients summing
//      to zero, and sum S_i y_i is the centroid of the part of the domain on the grid (the
//      functions differ from the open-knot basis of paper 002 there, which adds a control
//      point per side that is not a grid node);
//   4. crossing the face x = x0 + 2 h between cells (1, 2) and (2, 2) with each cell's patch:
//      values and gradients continuous (C1: they change by O(eps / h), about 1e-8, over
//      2 eps = 2e-9 h); each point talks to at most 9 distinct nodes.
// Numbers of order one computed in a few dozen operations: tolerance 1e-13 (round-off; a
// wrong half-width, a missing cell of the patch or an off-by-one node gives 1e-2 or more).
// Exits non-zero on failure.
#include "patch_grid.h"
#include "unit_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <slidewave/grid/quadratic_bspline.h>
#include <vector>

using namespace slidewave::grid;
using namespace patch_grid;
using unit_check::check;

namespace
{
  const double tolerance = 1e-13;

  Merged
  bspline(const Grid &grid, const std::vector<PatchCell> &patch, const double x, const double y)
  {
    NodeWeights w;
    bspline_weights(patch.data(), patch.data() + patch.size(), x, y, w);
    return merge(w, grid);
  }

  /** Node @p node's function at @p x by paper 002's Cox-de Boor basis @p basis on knots
   *  half a cell outside the grid's first node (its function node + 1). */
  void
  cox_de_boor(const QuadraticBSpline &basis,
              const unsigned int      node,
              const double            x,
              double                 &value,
              double                 &derivative)
  {
    std::array<double, 3> v, d;
    basis.evaluate(x, v, d);
    const unsigned int first = basis.cell(x), k = node + 1;
    value = derivative = 0.;
    if (k >= first && k < first + 3)
      {
        value      = v[k - first];
        derivative = d[k - first];
      }
  }

  /** Positions in a cell as fractions of h: a regular set (0 is on the face), the
   *  middle, where the domain's edge meets a node, and just before the next face. */
  std::vector<double>
  fractions()
  {
    std::vector<double> f;
    for (unsigned int k = 0; k < 20; ++k)
      f.push_back(k / 20.);
    f.push_back(0.5 - 1e-9);
    f.push_back(0.5 + 1e-9);
    f.push_back(1. - 1e-9);
    return f;
  }
} // namespace

int
main()
{
  const double h = 0.5;
  const Grid   grid{6, 6, -0.75, 1.25, h};
  std::printf("grid: 6 x 6 cells of h = %.2f from (%.2f, %.2f)\n", h, grid.x0, grid.y0);
  // The Cox-de Boor bases along x and y: 7 cells from half a cell before the first node
  // to half a cell after the last, knots through the cells' middles.
  const QuadraticBSpline along_x(grid.x0 - 0.5 * h, grid.x0 + 6.5 * h, 7);
  const QuadraticBSpline along_y(grid.y0 - 0.5 * h, grid.y0 + 6.5 * h, 7);

  // 1 and 2: the interior.
  {
    const std::vector<PatchCell> patch = grid.patch(2, 2);
    std::printf("interior: points in cell (2, 2), patch of %u cells\n",
                static_cast<unsigned int>(patch.size()));
    double closed_value = 0., closed_gradient = 0., recursion_value = 0., recursion_gradient = 0.,
           unity = 0., gradient_sum = 0., completeness = 0., gradient_completeness = 0.;
    unsigned int n_points = 0, most_nodes = 0;
    for (const double fx : fractions())
      for (const double fy : fractions())
        {
          const double x = grid.x0 + (2. + fx) * h, y = grid.y0 + (2. + fy) * h;
          const Merged m     = bspline(grid, patch, x, y);
          unsigned int nodes = 0;
          for (unsigned int n = 0; n < grid.n_nodes(); ++n)
            {
              nodes += m.value[n] != 0. || m.grad_x[n] != 0. || m.grad_y[n] != 0.;
              double sx, dsx, sy, dsy;
              bspline_1d(x, grid.node_x(n), h, sx, dsx);
              bspline_1d(y, grid.node_y(n), h, sy, dsy);
              closed_value    = std::max(closed_value, std::abs(m.value[n] - sx * sy));
              closed_gradient = std::max({closed_gradient,
                                          h * std::abs(m.grad_x[n] - dsx * sy),
                                          h * std::abs(m.grad_y[n] - sx * dsy)});
              cox_de_boor(along_x, n % (grid.nx + 1), x, sx, dsx);
              cox_de_boor(along_y, n / (grid.nx + 1), y, sy, dsy);
              recursion_value    = std::max(recursion_value, std::abs(m.value[n] - sx * sy));
              recursion_gradient = std::max({recursion_gradient,
                                             h * std::abs(m.grad_x[n] - dsx * sy),
                                             h * std::abs(m.grad_y[n] - sx * dsy)});
            }
          most_nodes      = std::max(most_nodes, nodes);
          const Moments r = moments(m, grid);
          unity           = std::max(unity, std::abs(r.sum - 1.));
          gradient_sum
            = std::max(gradient_sum, h * std::max(std::abs(r.sum_gx), std::abs(r.sum_gy)));
          completeness
            = std::max(completeness, std::max(std::abs(r.sx - x), std::abs(r.sy - y)) / h);
          gradient_completeness = std::max({gradient_completeness,
                                            std::abs(r.gx_x - 1.),
                                            std::abs(r.gy_x),
                                            std::abs(r.gx_y),
                                            std::abs(r.gy_y - 1.)});
          ++n_points;
        }
    std::printf("  %u positions, at most %u nodes per point\n", n_points, most_nodes);
    std::printf("  against 3/4 - s^2, (3/2 - |s|)^2 / 2: max |S - B B| = %.1e  max h |grad S - "
                "grad (B B)| = %.1e\n",
                closed_value,
                closed_gradient);
    std::printf("  against Cox-de Boor (QuadraticBSpline): max |S - N N| = %.1e  max h |grad S "
                "- grad (N N)| = %.1e\n",
                recursion_value,
                recursion_gradient);
    check(closed_value < tolerance && closed_gradient < tolerance,
          "bspline_weights is the tensor product of the uniform quadratic B-spline");
    check(recursion_value < tolerance && recursion_gradient < tolerance,
          "bspline_weights equals paper 002's Cox-de Boor basis in the interior");
    check(most_nodes == 9, "a point talks to 9 nodes");
    std::printf("  max |sum S - 1| = %.1e  max h |sum grad S| = %.1e  max |sum S x_i - x_p| / h "
                "= %.1e  max |sum grad S x_i - I| = %.1e\n",
                unity,
                gradient_sum,
                completeness,
                gradient_completeness);
    check(unity < tolerance && gradient_sum < tolerance,
          "partition of unity and sum of gradients zero");
    check(completeness < tolerance && gradient_completeness < tolerance,
          "linear completeness of values and gradients");
    // The cell's middle, half a cell from its nodes: B(1/2) = 1/2 at them and B(3/2) = 0
    // beyond, so S = 1/4 at the cell's four nodes.
    const Merged centred = bspline(grid, patch, grid.x0 + 2.5 * h, grid.y0 + 2.5 * h);
    std::printf("  cell's middle: S at its nodes %.15f %.15f %.15f %.15f\n",
                centred.value[grid.node(2, 2)],
                centred.value[grid.node(3, 2)],
                centred.value[grid.node(2, 3)],
                centred.value[grid.node(3, 3)]);
    // On a node: B(0) = 3/4 there and B(1) = 1/8 at its neighbours.
    const Merged on_node = bspline(grid, patch, grid.x0 + 2. * h, grid.y0 + 2. * h);
    std::printf("  on node (2, 2): S there %.15f, at (3, 2) %.15f, at (3, 3) %.15f\n",
                on_node.value[grid.node(2, 2)],
                on_node.value[grid.node(3, 2)],
                on_node.value[grid.node(3, 3)]);
  }

  // 3. The grid's lower side.
  {
    const std::vector<PatchCell> patch = grid.patch(2, 0);
    std::printf("grid boundary: cell (2, 0), patch of %u cells (none below y = %.2f):\n",
                static_cast<unsigned int>(patch.size()),
                grid.y0);
    double unity = 0., gradient_sum = 0., centroid = 0.;
    for (const double fx : fractions())
      for (const double fy : {0., 1e-9, 0.1, 0.25, 0.49, 0.5, 0.75})
        {
          const double  x = grid.x0 + (2. + fx) * h, y = grid.y0 + fy * h;
          const Moments r      = moments(bspline(grid, patch, x, y), grid);
          const double  bottom = std::max(y - 0.5 * h, grid.y0), top = y + 0.5 * h;
          unity = std::max(unity, std::abs(r.sum - 1.));
          gradient_sum
            = std::max(gradient_sum, h * std::max(std::abs(r.sum_gx), std::abs(r.sum_gy)));
          centroid
            = std::max(centroid,
                       std::max(std::abs(r.sx - x), std::abs(r.sy - 0.5 * (bottom + top))) / h);
        }
    std::printf("  max |sum S - 1| = %.1e  max h |sum grad S| = %.1e  max |centroid error| / h "
                "= %.1e\n",
                unity,
                gradient_sum,
                centroid);
    check(unity < tolerance && gradient_sum < tolerance,
          "next to the side: partition of unity and sum of gradients zero");
    check(centroid < tolerance,
          "next to the side: sum S x_i is the centroid of the domain on the grid");
  }

  // 4. Across the face x = x0 + 2h.
  {
    const double x_face = grid.x0 + 2. * h, eps = 1e-9 * h, y = grid.y0 + 2.3 * h;
    std::printf("crossing the face x = %.2f at y = %.2f, x = x_face -+ %.0e h:\n",
                x_face,
                y,
                eps / h);
    const Merged a          = bspline(grid, grid.patch(1, 2), x_face - eps, y);
    const Merged b          = bspline(grid, grid.patch(2, 2), x_face + eps, y);
    double       value_jump = 0., gradient_jump = 0.;
    for (unsigned int n = 0; n < grid.n_nodes(); ++n)
      {
        value_jump    = std::max(value_jump, std::abs(a.value[n] - b.value[n]));
        gradient_jump = std::max({gradient_jump,
                                  h * std::abs(a.grad_x[n] - b.grad_x[n]),
                                  h * std::abs(a.grad_y[n] - b.grad_y[n])});
      }
    std::printf("  max |jump of S| = %.1e  max h |jump of grad S| = %.1e\n",
                value_jump,
                gradient_jump);
    check(value_jump < 1e-6 && gradient_jump < 1e-6,
          "values and gradients continuous across the face");
  }

  return unit_check::finish();
}
