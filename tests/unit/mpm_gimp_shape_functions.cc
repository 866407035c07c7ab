// The material point shape functions of include/slidewave/grid/shape_functions.h on a
// hand-built uniform grid of PatchCell (cell size h = 0.5, origin (-0.75, 1.25), node ids
// i + (nx + 1) j on the lattice of vertices; each cell's patch is the cell itself first,
// then the cells sharing a vertex with it, as MaterialPointSolver builds it):
//   1. gimp_weights (cell-by-cell integration of Q1 over the particle's square domain)
//      equals the closed-form uGIMP function of paper 000, Eq. 11 (gimp_1d), as the
//      tensor product S_i(x) S_j(y), dS_i(x) S_j(y), S_i(x) dS_j(y), for 23 x 23 particle
//      positions in the centre cell of a 3 x 3 grid (on the faces, where the domain
//      touches a face, straddles a face or a corner, exactly centred) and half-lengths
//      lp = h/4 (2 points per cell) and h/6 (3 points per cell); entries of a node shared
//      by several cells are merged first;
//   2. for GIMP and Q1 (q1_weights): partition of unity, sum of gradients zero, linear
//      completeness sum S_i x_i = x_p and sum grad S_i x_i = (1, 0) (and the same in y);
//   3. a point near the grid boundary (a patch missing its lower row of cells) whose
//      domain pokes out of the grid: the values still sum to one, the gradients to zero,
//      and sum S_i y_i is the centroid of the part of the domain on the grid;
//   4. a particle crossing a cell face (x_face - eps in one cell with that cell's patch,
//      x_face + eps in the neighbour with the neighbour's patch): the GIMP values and
//      gradients are continuous (they change by O(eps / lp), about 1e-8 here, as any
//      smooth function does over 2 eps = 1e-9 h), Q1's gradients jump by 2 (1 - eta) / h
//      (printed scaled by h).
// All the comparisons are of numbers of order one (values, gradients times h, coordinates
// over h) computed in a few dozen floating point operations: the tolerance 1e-13 is
// round-off (a wrong formula or a missing cell gives errors of order 1e-3 or more).
// Exits non-zero on failure.
#include "patch_grid.h"
#include "unit_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <slidewave/grid/shape_functions.h>
#include <vector>

using namespace slidewave::grid;

using unit_check::check;
using namespace patch_grid;

namespace
{

  const double tolerance = 1e-13;


  /** Largest deviations (scaled to order one) from the partition of unity and linear
   * completeness at (x, y). */
  struct Deviations
  {
    double unity = 0., gradient_sum = 0., completeness = 0., gradient_completeness = 0.;

    void
    add(const Moments &r, const double x, const double y, const double h)
    {
      unity        = std::max(unity, std::abs(r.sum - 1.));
      gradient_sum = std::max(gradient_sum, h * std::max(std::abs(r.sum_gx), std::abs(r.sum_gy)));
      completeness = std::max(completeness, std::max(std::abs(r.sx - x), std::abs(r.sy - y)) / h);
      gradient_completeness = std::max({gradient_completeness,
                                        std::abs(r.gx_x - 1.),
                                        std::abs(r.gy_x),
                                        std::abs(r.gx_y),
                                        std::abs(r.gy_y - 1.)});
    }

    void
    report(const char *name) const
    {
      std::printf("  %s: max |sum S - 1| = %.1e  max h |sum grad S| = %.1e\n",
                  name,
                  unity,
                  gradient_sum);
      std::printf("  %s: max |sum S x_i - x_p| / h = %.1e  max |sum grad S x_i - I| = %.1e\n",
                  name,
                  completeness,
                  gradient_completeness);
      char what[200];
      std::snprintf(what, sizeof(what), "%s partition of unity and sum of gradients zero", name);
      check(unity < tolerance && gradient_sum < tolerance, what);
      std::snprintf(what, sizeof(what), "%s linear completeness of values and gradients", name);
      check(completeness < tolerance && gradient_completeness < tolerance, what);
    }
  };

  /** Positions in a cell as fractions of h: a regular set (0 is on the face) and the
   * places where the domain [x - lp, x + lp] touches a face. */
  std::vector<double>
  fractions(const double lp_over_h)
  {
    std::vector<double> f;
    for (unsigned int k = 0; k < 20; ++k)
      f.push_back(k / 20.);
    f.push_back(lp_over_h);
    f.push_back(1. - lp_over_h);
    f.push_back(1. - 1e-9);
    return f;
  }
} // namespace

int
main()
{
  const double h = 0.5;
  const Grid   grid{3, 3, -0.75, 1.25, h};
  std::printf("grid: 3 x 3 cells of h = %.2f from (%.2f, %.2f), particles in the centre cell "
              "[%.2f, %.2f] x [%.2f, %.2f]\n",
              h,
              grid.x0,
              grid.y0,
              grid.x0 + h,
              grid.x0 + 2 * h,
              grid.y0 + h,
              grid.y0 + 2 * h);
  const std::vector<PatchCell> centre_patch = grid.patch(1, 1);
  std::printf("centre cell patch: %u cells\n", static_cast<unsigned int>(centre_patch.size()));

  // 1 and 2: GIMP against Eq. 11, partition of unity, completeness.
  for (const unsigned int per_cell : {2u, 3u})
    {
      const double lp = h / (2. * per_cell);
      std::printf("GIMP, lp = h/%u = %.6f:\n", 2 * per_cell, lp);
      const std::vector<double> f           = fractions(lp / h);
      double                    value_error = 0., gradient_error = 0.;
      unsigned int n_points = 0, max_entries = 0, n_straddle_face = 0, n_straddle_corner = 0;
      Deviations   deviations;
      for (const double fx : f)
        for (const double fy : f)
          {
            const double x = grid.x0 + h + fx * h;
            const double y = grid.y0 + h + fy * h;
            NodeWeights  w;
            gimp_weights(
              centre_patch.data(), centre_patch.data() + centre_patch.size(), x, y, lp, lp, w);
            max_entries        = std::max(max_entries, w.n);
            const Merged m     = merge(w, grid);
            const bool   out_x = fx * h < lp || fx * h > h - lp;
            const bool   out_y = fy * h < lp || fy * h > h - lp;
            n_straddle_face += out_x != out_y;
            n_straddle_corner += out_x && out_y;
            for (unsigned int n = 0; n < grid.n_nodes(); ++n)
              {
                double sx, dsx, sy, dsy;
                gimp_1d(x, grid.node_x(n), h, lp, sx, dsx);
                gimp_1d(y, grid.node_y(n), h, lp, sy, dsy);
                value_error    = std::max(value_error, std::abs(m.value[n] - sx * sy));
                gradient_error = std::max({gradient_error,
                                           h * std::abs(m.grad_x[n] - dsx * sy),
                                           h * std::abs(m.grad_y[n] - sx * dsy)});
              }
            deviations.add(moments(m, grid), x, y, h);
            ++n_points;
          }
      std::printf("  %u positions (%u with the domain across one face, %u across a corner), "
                  "at most %u entries\n",
                  n_points,
                  n_straddle_face,
                  n_straddle_corner,
                  max_entries);
      std::printf("  max |S - S_Eq.11| = %.1e  max h |grad S - grad S_Eq.11| = %.1e\n",
                  value_error,
                  gradient_error);
      check(value_error < tolerance && gradient_error < tolerance,
            "gimp_weights equals the tensor product of Eq. 11");
      deviations.report("GIMP");

      // The centred point: |x - x_i| = h/2 lies in [lp, h - lp], where Eq. 11 is the Q1
      // hat 1 - |x - x_i|/h = 1/2, so S = 1/4 at each of the cell's own four nodes.
      const Merged centred = gimp(grid, centre_patch, grid.x0 + 1.5 * h, grid.y0 + 1.5 * h, lp);
      std::printf("  centred point: S at the cell's nodes %.15f %.15f %.15f %.15f\n",
                  centred.value[grid.node(1, 1)],
                  centred.value[grid.node(2, 1)],
                  centred.value[grid.node(1, 2)],
                  centred.value[grid.node(2, 2)]);
    }

  // 2 for Q1.
  {
    std::printf("Q1:\n");
    const std::vector<double> f = fractions(0.25);
    Deviations                deviations;
    for (const double fx : f)
      for (const double fy : f)
        {
          NodeWeights w;
          q1_weights(centre_patch[0], fx, fy, w);
          deviations.add(moments(merge(w, grid), grid),
                         grid.x0 + h + fx * h,
                         grid.y0 + h + fy * h,
                         h);
        }
    deviations.report("Q1");
  }

  // 3. The bottom row of the grid: the patch of cell (1, 0) has no cells below it.
  {
    const std::vector<PatchCell> patch = grid.patch(1, 0);
    std::printf("grid boundary: cell (1, 0), patch of %u cells (none below y = %.2f):\n",
                static_cast<unsigned int>(patch.size()),
                grid.y0);
    double unity = 0., gradient_sum = 0., centroid = 0., gradient_completeness = 0.;
    for (const double lp : {h / 4., h / 6.})
      for (const double fx : fractions(lp / h))
        for (const double fy : {0., 1e-9, 0.05, 0.1, lp / (2. * h), lp / h - 1e-9})
          {
            const double  x = grid.x0 + h + fx * h, y = grid.y0 + fy * h;
            const Moments r = moments(gimp(grid, patch, x, y, lp), grid);
            // Centroid of [y - lp, y + lp] cut at the grid's lower side.
            const double bottom = std::max(y - lp, grid.y0), top = y + lp;
            unity = std::max(unity, std::abs(r.sum - 1.));
            gradient_sum
              = std::max(gradient_sum, h * std::max(std::abs(r.sum_gx), std::abs(r.sum_gy)));
            centroid
              = std::max(centroid,
                         std::max(std::abs(r.sx - x), std::abs(r.sy - 0.5 * (bottom + top))) / h);
            gradient_completeness = std::max({gradient_completeness,
                                              std::abs(r.gx_x - 1.),
                                              std::abs(r.gy_x),
                                              std::abs(r.gx_y),
                                              std::abs(r.gy_y - 1.)});
          }
    const Moments r
      = moments(gimp(grid, patch, grid.x0 + 1.3 * h, grid.y0 + 0.05 * h, h / 4.), grid);
    std::printf("  point (%.4f, %.4f), lp = h/4: sum S = %.15f  sum S y_i = %.15f "
                "(centroid of the domain on the grid %.15f)\n",
                grid.x0 + 1.3 * h,
                grid.y0 + 0.05 * h,
                r.sum,
                r.sy,
                0.5 * (grid.y0 + grid.y0 + 0.05 * h + h / 4.));
    std::printf("  max |sum S - 1| = %.1e  max h |sum grad S| = %.1e  max |centroid error| / h "
                "= %.1e  max |sum grad S x_i - I| = %.1e\n",
                unity,
                gradient_sum,
                centroid,
                gradient_completeness);
    check(unity < tolerance && gradient_sum < tolerance,
          "domain out of the grid: partition of unity and sum of gradients zero");
    check(centroid < tolerance && gradient_completeness < tolerance,
          "domain out of the grid: sum S x_i is the centroid of the domain on the grid");
  }

  // 4. Crossing the face x = x0 + 2h between cells (1, 1) and (2, 1) of a 4 x 3 grid.
  {
    const Grid   wide{4, 3, grid.x0, grid.y0, h};
    const double x_face = wide.x0 + 2. * h, eps = 1e-9 * h, eta = 0.3;
    const double y = wide.y0 + (1. + eta) * h;
    std::printf("crossing the face x = %.2f at y = %.2f (eta = %.1f), x = x_face -+ %.0e h:\n",
                x_face,
                y,
                eta,
                eps / h);
    const std::vector<PatchCell> left = wide.patch(1, 1), right = wide.patch(2, 1);
    for (const double lp : {h / 4., h / 6.})
      {
        const Merged a          = gimp(wide, left, x_face - eps, y, lp);
        const Merged b          = gimp(wide, right, x_face + eps, y, lp);
        double       value_jump = 0., gradient_jump = 0.;
        for (unsigned int n = 0; n < wide.n_nodes(); ++n)
          {
            value_jump    = std::max(value_jump, std::abs(a.value[n] - b.value[n]));
            gradient_jump = std::max({gradient_jump,
                                      h * std::abs(a.grad_x[n] - b.grad_x[n]),
                                      h * std::abs(a.grad_y[n] - b.grad_y[n])});
          }
        std::printf("  GIMP lp = h/%.0f: max |jump of S| = %.1e  max h |jump of grad S| = "
                    "%.1e\n",
                    h / lp,
                    value_jump,
                    gradient_jump);
        check(value_jump < 1e-6 && gradient_jump < 1e-6,
              "GIMP values and gradients continuous across the face");
      }
    NodeWeights wa, wb;
    q1_weights(left[0], 1. - eps / h, eta, wa);
    q1_weights(right[0], eps / h, eta, wb);
    const Merged a = merge(wa, wide), b = merge(wb, wide);
    double       value_jump = 0., gradient_jump = 0.;
    for (unsigned int n = 0; n < wide.n_nodes(); ++n)
      {
        value_jump    = std::max(value_jump, std::abs(a.value[n] - b.value[n]));
        gradient_jump = std::max({gradient_jump,
                                  h * std::abs(a.grad_x[n] - b.grad_x[n]),
                                  h * std::abs(a.grad_y[n] - b.grad_y[n])});
      }
    std::printf("  Q1: max |jump of S| = %.1e  max h |jump of grad S| = %.6f (2 (1 - eta) = "
                "%.6f)\n",
                value_jump,
                gradient_jump,
                2. * (1. - eta));
    check(value_jump < 1e-6 && std::abs(gradient_jump - 2. * (1. - eta)) < 1e-6,
          "Q1 values continuous, gradients jump by 2 (1 - eta) / h");
  }

  return unit_check::finish();
}
