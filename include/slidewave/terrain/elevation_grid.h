#ifndef slidewave_terrain_elevation_grid_h
#define slidewave_terrain_elevation_grid_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <functional>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    /**
     * A terrain Z(x, y) as elevations on a regular grid of nodes (a raster's pixel centres,
     * or an expression sampled once), with the bilinear interpolant between them: the form
     * every source takes (an expression, a table, later a DEM read through GDAL), so that
     * the per-point work of a model over the terrain is one non-virtual bilinear lookup.
     *
     * value() is the bilinear interpolant; gradient() is its exact gradient inside the cell
     * that holds the point (constant along x within a cell row for d/dy and along y for
     * d/dx, discontinuous across cell faces, where the cell on the higher-index side is
     * used). A plane is reproduced exactly, value and gradient, at any point. Outside the
     * grid the nearest cell's interpolant is extended (linear extrapolation); callers that
     * must not leave the grid check contains().
     */
    class ElevationGrid
    {
    public:
      /** Nodes x0 + i dx, y0 + j dy, i < nx, j < ny; @p values row by row (i fastest),
       *  finite, or NaN for a gap (no data) when @p with_gaps. */
      ElevationGrid(const dealii::Point<2> &origin,
                    double                  dx,
                    double                  dy,
                    unsigned int            nx,
                    unsigned int            ny,
                    std::vector<double>     values,
                    bool                    with_gaps = false);

      /** Samples @p z at the nodes of an nx x ny grid spanning [lower, upper]. */
      static ElevationGrid
      from_function(const std::function<double(double, double)> &z,
                    const dealii::Point<2>                      &lower,
                    const dealii::Point<2>                      &upper,
                    unsigned int                                 nx,
                    unsigned int                                 ny);

      double
      value(const dealii::Point<2> &p) const
      {
        double             fx, fy;
        const unsigned int k = locate(p, fx, fy);
        const double       a = z[k], b = z[k + 1], c = z[k + nx], d = z[k + nx + 1];
        return (1. - fy) * ((1. - fx) * a + fx * b) + fy * ((1. - fx) * c + fx * d);
      }

      dealii::Tensor<1, 2>
      gradient(const dealii::Point<2> &p) const
      {
        double               fx, fy;
        const unsigned int   k = locate(p, fx, fy);
        const double         a = z[k], b = z[k + 1], c = z[k + nx], d = z[k + nx + 1];
        dealii::Tensor<1, 2> g;
        g[0] = ((1. - fy) * (b - a) + fy * (d - c)) / dx;
        g[1] = ((1. - fx) * (c - a) + fx * (d - b)) / dy;
        return g;
      }

      /** value() and gradient() with one lookup. */
      double
      value_and_gradient(const dealii::Point<2> &p, dealii::Tensor<1, 2> &g) const
      {
        double             fx, fy;
        const unsigned int k = locate(p, fx, fy);
        const double       a = z[k], b = z[k + 1], c = z[k + nx], d = z[k + nx + 1];
        g[0] = ((1. - fy) * (b - a) + fy * (d - c)) / dx;
        g[1] = ((1. - fx) * (c - a) + fx * (d - b)) / dy;
        return (1. - fy) * ((1. - fx) * a + fx * b) + fy * ((1. - fx) * c + fx * d);
      }

      /** The value at the node nearest to @p p: a raster's value over the pixel that holds
       *  @p p, when the nodes are its pixel centres. */
      double
      nearest_value(const dealii::Point<2> &p) const
      {
        double             fx, fy;
        const unsigned int k = locate(p, fx, fy);
        return z[k + (fx >= 0.5 ? 1 : 0) + (fy >= 0.5 ? nx : 0)];
      }

      bool
      contains(const dealii::Point<2> &p) const;

      dealii::Point<2>
      lower() const
      {
        return origin;
      }

      dealii::Point<2>
      upper() const
      {
        return origin + dealii::Point<2>((nx - 1) * dx, (ny - 1) * dy);
      }

    private:
      /** The lower-left node of the cell used for @p p and the local coordinates in it
       *  (in [0, 1] inside the grid, beyond when extrapolating). */
      unsigned int
      locate(const dealii::Point<2> &p, double &fx, double &fy) const
      {
        const double       sx = (p[0] - origin[0]) / dx, sy = (p[1] - origin[1]) / dy;
        const unsigned int i = cell_index(sx, nx), j = cell_index(sy, ny);
        fx = sx - i;
        fy = sy - j;
        return j * nx + i;
      }

      static unsigned int
      cell_index(const double s, const unsigned int n)
      {
        if (!(s > 0.))
          return 0;
        const double last = static_cast<double>(n - 2);
        return s >= last ? n - 2 : static_cast<unsigned int>(s);
      }

      dealii::Point<2>    origin;
      double              dx, dy;
      unsigned int        nx, ny;
      std::vector<double> z;
    };
  } // namespace terrain
} // namespace slidewave

#endif
