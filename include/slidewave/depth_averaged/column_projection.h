#ifndef slidewave_depth_averaged_column_projection_h
#define slidewave_depth_averaged_column_projection_h

#include <cstdint>
#include <deal.II/base/point.h>
#include <slidewave/depth_averaged/tiled_raster.h>
#include <slidewave/particles/point_cloud.h>
#include <utility>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * The flow thickness and velocity of the hazard maps on a fixed raster of pixels,
     * projected straight from the columns (issue 28): pixel i is centred on the node x_i of
     * the uniform grid of 'Cell size' c, with that grid's hat function N_i (bilinear, 1 at
     * x_i, 0 a cell away) and lumped area a_i = integral of N_i over the domain. Column p
     * stands for a rectangle R_p of its own area A_p = V_p / h_p centred on it (the
     * proportions of its GIMP domain; half-sides at most 2 c), clipped to the domain, over
     * which it spreads its volume V_p, mass m_p and momentum m_p v_p evenly: its weight at
     * node i is the GIMP weight S_ip = (1 / |R_p|) integral over R_p of N_i, and
     *
     *   h_i = sum_p V_p S_ip / a_i,
     *   v_i = sum_p m_p v_p S_ip / sum_p m_p S_ip.
     *
     * Why not the nodal projection sum_p V_p N_i(x_p) / a_i of the step: where the columns
     * have spread to about a cell apart, how many of them fall near a node and how near is
     * an accident of their positions, and the projected thickness shows stripes one to two
     * cells wide (doc/terrain.md). The rectangles of a layer tile the plane whatever their
     * positions, so a uniform layer gives its depth exactly on every pixel whose hat it
     * covers, and the hats smooth what the columns' own depths scatter; the weights of a
     * column sum to 1, so sum_i h_i a_i is the columns' volume; and the maps need nothing
     * from the grid: they are the same on a uniform and on an adaptive grid.
     *
     * Cost: one pass over the columns (four to nine pixels each) into sparse tiles; on
     * several ranks the touched pixels' sums (not the raster) are gathered on rank 0, which
     * holds the maps.
     */
    class ColumnProjection
    {
    public:
      /** A pixel the flow covers now: its index j * (nx + 1) + i, thickness and velocity. */
      struct Pixel
      {
        std::uint64_t index;
        double        depth, velocity_x, velocity_y;
      };

      /** The raster of (nx + 1) x (ny + 1) pixels of side @p cell_size centred on the
       *  nodes from @p lower_left. */
      ColumnProjection(const dealii::Point<2> &lower_left,
                       double                  cell_size,
                       unsigned int            nx,
                       unsigned int            ny);

      /** The pixels the columns of @p cloud cover now, on rank 0 (in the order their
       *  sums were first touched; empty on the other ranks). Collective. */
      const std::vector<Pixel> &
      project(const particles::PointCloud &cloud);

    private:
      /** Adds the column at @p x (volume @p V, mass @p m, velocity, rectangle of half-sides
       *  @p bx, @p by) to the sums. */
      void
      add_column(const dealii::Point<2> &x,
                 double                  V,
                 double                  m,
                 double                  vx,
                 double                  vy,
                 double                  bx,
                 double                  by);

      /** Adds @p values (volume, mass, momentum x, y) to pixel (@p i, @p j). */
      void
      add(const unsigned int i, const unsigned int j, const double *values)
      {
        double *s = sums.at(i, j);
        // A column's mass is positive: a pixel with none has not been touched yet.
        if (s[1] == 0.)
          touched.push_back(static_cast<std::uint64_t>(j) * (nx + 1) + i);
        for (unsigned int v = 0; v < 4; ++v)
          s[v] += values[v];
      }

      /** The mean over [@p a, @p b] (inside [@p origin, @p origin + @p n c]) of the hat
       *  of each node it reaches, into @p weights: the first node's index and how many. */
      std::pair<unsigned int, unsigned int>
      hat_weights(double a, double b, double origin, unsigned int n, double *weights) const;

      /** The most nodes a column's rectangle (at most 4 c along a side) reaches along x. */
      static constexpr unsigned int max_reach = 8;

      /** Rank 0 receives the other ranks' touched sums (collective). */
      void
      gather_on_rank_zero();

      dealii::Point<2>           corner;
      double                     c;
      unsigned int               nx, ny;
      TiledRaster                sums;
      std::vector<std::uint64_t> touched;
      std::vector<Pixel>         pixels;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
