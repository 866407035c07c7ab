#ifndef slidewave_tests_patch_grid_h
#define slidewave_tests_patch_grid_h

#include <slidewave/grid/shape_functions.h>
#include <vector>

// A hand-built uniform grid of grid::PatchCell for the shape-function tests (node ids
// i + (nx + 1) j on the lattice of vertices; each cell's patch is the cell itself first,
// then the cells sharing a vertex with it, as CellPatches builds it), and the sums over
// its nodes that partition of unity and linear completeness are checked with.
namespace patch_grid
{
  using namespace slidewave::grid;

  /** A uniform grid of nx x ny cells of size h with lower left corner (x0, y0). */
  struct Grid
  {
    unsigned int nx, ny;
    double       x0, y0, h;

    unsigned int
    n_nodes() const
    {
      return (nx + 1) * (ny + 1);
    }

    unsigned int
    node(const unsigned int i, const unsigned int j) const
    {
      return i + (nx + 1) * j;
    }

    double
    node_x(const unsigned int n) const
    {
      return x0 + (n % (nx + 1)) * h;
    }

    double
    node_y(const unsigned int n) const
    {
      return y0 + (n / (nx + 1)) * h;
    }

    PatchCell
    cell(const unsigned int i, const unsigned int j) const
    {
      PatchCell c;
      c.x0      = x0 + i * h;
      c.y0      = y0 + j * h;
      c.hx      = h;
      c.hy      = h;
      c.node[0] = node(i, j);
      c.node[1] = node(i + 1, j);
      c.node[2] = node(i, j + 1);
      c.node[3] = node(i + 1, j + 1);
      return c;
    }

    /** Cell (i, j) first, then the cells of the grid sharing a vertex with it. */
    std::vector<PatchCell>
    patch(const unsigned int i, const unsigned int j) const
    {
      std::vector<PatchCell> cells{cell(i, j)};
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          {
            const int a = static_cast<int>(i) + di, b = static_cast<int>(j) + dj;
            if ((di != 0 || dj != 0) && a >= 0 && b >= 0 && a < static_cast<int>(nx)
                && b < static_cast<int>(ny))
              cells.push_back(cell(a, b));
          }
      return cells;
    }
  };

  /** Per node of the grid: value, gradient (entries of shared nodes summed). */
  struct Merged
  {
    std::vector<double> value, grad_x, grad_y;
  };

  inline Merged
  merge(const NodeWeights &w, const Grid &grid)
  {
    Merged m;
    m.value.assign(grid.n_nodes(), 0.);
    m.grad_x.assign(grid.n_nodes(), 0.);
    m.grad_y.assign(grid.n_nodes(), 0.);
    for (unsigned int k = 0; k < w.n; ++k)
      {
        m.value[w.node[k]] += w.value[k];
        m.grad_x[w.node[k]] += w.grad_x[k];
        m.grad_y[w.node[k]] += w.grad_y[k];
      }
    return m;
  }

  inline Merged
  gimp(const Grid                   &grid,
       const std::vector<PatchCell> &patch,
       const double                  x,
       const double                  y,
       const double                  lp)
  {
    NodeWeights w;
    gimp_weights(patch.data(), patch.data() + patch.size(), x, y, lp, lp, w);
    return merge(w, grid);
  }

  /** Sums over the nodes, for the partition of unity and completeness checks. */
  struct Moments
  {
    double sum = 0., sum_gx = 0., sum_gy = 0.;
    double sx = 0., sy = 0.;     // sum S_i x_i, sum S_i y_i
    double gx_x = 0., gy_x = 0.; // sum grad S_i x_i
    double gx_y = 0., gy_y = 0.; // sum grad S_i y_i
  };

  inline Moments
  moments(const Merged &m, const Grid &grid)
  {
    Moments r;
    for (unsigned int n = 0; n < grid.n_nodes(); ++n)
      {
        const double xn = grid.node_x(n), yn = grid.node_y(n);
        r.sum += m.value[n];
        r.sum_gx += m.grad_x[n];
        r.sum_gy += m.grad_y[n];
        r.sx += m.value[n] * xn;
        r.sy += m.value[n] * yn;
        r.gx_x += m.grad_x[n] * xn;
        r.gy_x += m.grad_y[n] * xn;
        r.gx_y += m.grad_x[n] * yn;
        r.gy_y += m.grad_y[n] * yn;
      }
    return r;
  }
} // namespace patch_grid

#endif
