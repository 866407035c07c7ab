#ifndef slidewave_grid_shape_functions_h
#define slidewave_grid_shape_functions_h

#include <algorithm>
#include <deal.II/base/tensor.h>

namespace slidewave
{
  namespace grid
  {
    /** How a material point is connected to the nodes of the background grid. */
    enum class ShapeFunction
    {
      q1,     ///< standard bilinear shape functions of the cell holding the point
      gimp,   ///< uGIMP: Q1 averaged over a fixed square domain around the point (Eq. 11)
      cpgimp, ///< GIMP with a rectangular domain stretched with the point (contiguous particle)
      bspline ///< quadratic B-splines centred on the nodes (bspline_weights)
    };

    /**
     * One active cell of the patch around a cell: its axis-aligned box and the local
     * (vector) indices of its four Q1 nodes in deal.II's order (0,0), (1,0), (0,1), (1,1).
     */
    struct PatchCell
    {
      double       x0, y0, hx, hy;
      unsigned int node[4];
    };

    /**
     * The nodes a material point talks to and its shape function values and gradients
     * there. A node shared by two of the cells the point's domain overlaps appears twice,
     * each time with the part of the integral that lies in that cell; scattering and
     * gathering with the list gives the same sums as merging them first.
     */
    struct NodeWeights
    {
      static constexpr unsigned int max_entries = 16; // four cells of four nodes

      unsigned int n = 0;
      unsigned int node[max_entries];
      double       value[max_entries], grad_x[max_entries], grad_y[max_entries];
    };

    /**
     * Q1 on the cell @p cell at reference point (xi, eta).
     */
    inline void
    q1_weights(const PatchCell &cell, const double xi, const double eta, NodeWeights &w)
    {
      const double inv_hx = 1. / cell.hx, inv_hy = 1. / cell.hy;
      w.n         = 4;
      w.value[0]  = (1. - xi) * (1. - eta);
      w.value[1]  = xi * (1. - eta);
      w.value[2]  = (1. - xi) * eta;
      w.value[3]  = xi * eta;
      w.grad_x[0] = -(1. - eta) * inv_hx;
      w.grad_x[1] = (1. - eta) * inv_hx;
      w.grad_x[2] = -eta * inv_hx;
      w.grad_x[3] = eta * inv_hx;
      w.grad_y[0] = -(1. - xi) * inv_hy;
      w.grad_y[1] = -xi * inv_hy;
      w.grad_y[2] = (1. - xi) * inv_hy;
      w.grad_y[3] = xi * inv_hy;
      for (unsigned int a = 0; a < 4; ++a)
        w.node[a] = cell.node[a];
    }

    /**
     * GIMP: the Q1 shape functions averaged over the point's domain
     * [x - lx, x + lx] x [y - ly, y + ly], integrated exactly cell by cell over the cells
     * of @p patch (the cells sharing a vertex with the point's cell) that the domain
     * overlaps:
     *
     *   S_i = (1/|D|) sum_K int_{D cap K} N_i^K,   grad S_i = (1/|D|) sum_K int_{D cap K} grad
     * N_i^K.
     *
     * On a uniform grid this is the uGIMP function of paper 000, Eq. 11 (Bardenhagen and
     * Kober 2004), C1 across cell faces. Built from whole cells, it stays right where the
     * cells differ in size. |D| is the part of the domain that lies on the grid, so the
     * functions sum to one (mass and momentum are conserved) even where a point's domain
     * pokes out of the grid.
     */
    inline void
    gimp_weights(const PatchCell *patch_begin,
                 const PatchCell *patch_end,
                 const double     x,
                 const double     y,
                 const double     lx,
                 const double     ly,
                 NodeWeights     &w)
    {
      w.n               = 0;
      const double left = x - lx, right = x + lx, bottom = y - ly, top = y + ly;
      double       area = 0.;
      for (const PatchCell *cell = patch_begin; cell != patch_end; ++cell)
        {
          const double a = std::max(left, cell->x0), b = std::min(right, cell->x0 + cell->hx);
          if (!(b > a))
            continue;
          const double c = std::max(bottom, cell->y0), d = std::min(top, cell->y0 + cell->hy);
          if (!(d > c))
            continue;
          // 1D integrals of the two linear functions over [a, b] (in x) and [c, d] (in y),
          // and of their derivatives.
          const double xa = (a - cell->x0) / cell->hx, xb = (b - cell->x0) / cell->hx;
          const double ix1 = 0.5 * cell->hx * (xb * xb - xa * xa);
          const double ix0 = (b - a) - ix1;
          const double dx1 = xb - xa; // (b - a) / hx
          const double ya = (c - cell->y0) / cell->hy, yb = (d - cell->y0) / cell->hy;
          const double iy1   = 0.5 * cell->hy * (yb * yb - ya * ya);
          const double iy0   = (d - c) - iy1;
          const double dy1   = yb - ya;
          const double ix[2] = {ix0, ix1}, iy[2] = {iy0, iy1};
          const double dx[2] = {-dx1, dx1}, dy[2] = {-dy1, dy1};
          for (unsigned int j = 0; j < 2; ++j)
            for (unsigned int i = 0; i < 2; ++i)
              {
                const unsigned int k = w.n++;
                w.node[k]            = cell->node[2 * j + i];
                w.value[k]           = ix[i] * iy[j];
                w.grad_x[k]          = dx[i] * iy[j];
                w.grad_y[k]          = ix[i] * dy[j];
              }
          area += (b - a) * (d - c);
        }
      const double inv_area = 1. / area;
      for (unsigned int k = 0; k < w.n; ++k)
        {
          w.value[k] *= inv_area;
          w.grad_x[k] *= inv_area;
          w.grad_y[k] *= inv_area;
        }
    }

    /**
     * The 1D uGIMP function of paper 000, Eq. 11, for a node at @p xi, cell size @p h and
     * domain half-length @p lp (lp <= h/2), and its derivative: closed form, used to check
     * gimp_weights.
     */
    inline void
    gimp_1d(const double x,
            const double xi,
            const double h,
            const double lp,
            double      &value,
            double      &derivative)
    {
      const double r = x - xi, s = r < 0. ? -1. : 1., ar = std::abs(r);
      if (ar < lp)
        {
          value      = 1. - (r * r + lp * lp) / (2. * h * lp);
          derivative = -r / (h * lp);
        }
      else if (ar < h - lp)
        {
          value      = 1. - ar / h;
          derivative = -s / h;
        }
      else if (ar < h + lp)
        {
          value      = (h + lp - ar) * (h + lp - ar) / (4. * h * lp);
          derivative = -s * (h + lp - ar) / (2. * h * lp);
        }
      else
        {
          value      = 0.;
          derivative = 0.;
        }
    }
    /**
     * Quadratic B-splines centred on the grid's nodes (Steffen, Kirby and Berzins 2008;
     * paper 002, Appendix A, builds quadratic B-splines by Cox-de Boor: on knots through
     * the cells' middles its interior functions are these):
     * node i's function is B((x - x_i) / h) B((y - y_i) / h) with the uniform quadratic
     * B-spline B(s) = 3/4 - s^2 for |s| <= 1/2, (3/2 - |s|)^2 / 2 for 1/2 <= |s| <= 3/2,
     * C1, support three cells. B is the hat convolved with the unit box (the hat is the box
     * convolved with itself), so B-splines are GIMP with the point's domain a whole cell of
     * the point's cell: half-lengths hx/2, hy/2, whatever the points per cell. Where that
     * domain pokes out of the grid (a point within half a cell of its edge), gimp_weights
     * keeps the part on the grid, so the functions still sum to one there (paper 002's
     * open knot vector instead adds a function per side, whose control point is not a grid
     * node). Uniform grids only: where cells change size the domain would jump with the
     * point's cell (the scenes refuse 'bspline' with an adaptive grid).
     */
    inline void
    bspline_weights(const PatchCell *patch_begin,
                    const PatchCell *patch_end,
                    const double     x,
                    const double     y,
                    NodeWeights     &w)
    {
      gimp_weights(patch_begin, patch_end, x, y, 0.5 * patch_begin->hx, 0.5 * patch_begin->hy, w);
    }

    /**
     * The uniform quadratic B-spline B((x - xi) / h) of bspline_weights and its derivative
     * in x, closed form: used to check bspline_weights.
     */
    inline void
    bspline_1d(const double x, const double xi, const double h, double &value, double &derivative)
    {
      const double s = (x - xi) / h, as = std::abs(s), sign = s < 0. ? -1. : 1.;
      if (as <= 0.5)
        {
          value      = 0.75 - s * s;
          derivative = -2. * s / h;
        }
      else if (as < 1.5)
        {
          value      = 0.5 * (1.5 - as) * (1.5 - as);
          derivative = -sign * (1.5 - as) / h;
        }
      else
        {
          value      = 0.;
          derivative = 0.;
        }
    }

    /**
     * cpGIMP: a point's domain follows its stretch along the axes, half-lengths
     * @p half_x, @p half_y times 1 + L_xx dt and 1 + L_yy dt, kept within @p max_half (half
     * a cell) so that it stays inside the patch of cells.
     */
    inline void
    stretch_domain(double                     &half_x,
                   double                     &half_y,
                   const dealii::Tensor<2, 2> &L,
                   const double                dt,
                   const double                max_half)
    {
      half_x = std::min(max_half, half_x * (1. + L[0][0] * dt));
      half_y = std::min(max_half, half_y * (1. + L[1][1] * dt));
    }
  } // namespace grid
} // namespace slidewave

#endif
