#include <algorithm>
#include <cmath>
#include <deal.II/base/mpi.h>
#include <slidewave/depth_averaged/column_projection.h>
#include <slidewave/depth_averaged/depth_averaged_model.h>

namespace slidewave
{
  namespace depth_averaged
  {
    namespace
    {
      /** Values per pixel: volume, mass, momentum x, momentum y. */
      constexpr unsigned int n_sums = 4;
    } // namespace



    ColumnProjection::ColumnProjection(const dealii::Point<2> &lower_left,
                                       const double            cell_size,
                                       const unsigned int      nx,
                                       const unsigned int      ny)
      : corner(lower_left)
      , c(cell_size)
      , nx(nx)
      , ny(ny)
      , sums(nx + 1, ny + 1, std::vector<double>(n_sums, 0.))
    {
    }



    std::pair<unsigned int, unsigned int>
    ColumnProjection::hat_weights(const double       a,
                                  const double       b,
                                  const double       origin,
                                  const unsigned int n,
                                  double            *weights) const
    {
      // [a, b] in cell units from the origin, inside [0, n]; cell k = [k, k + 1] gives its
      // node k the integral of 1 - s over its part [s_a, s_b] of the segment and node
      // k + 1 that of s. The segment is at most 4 cells long: at most 6 nodes.
      const double       sa = (a - origin) / c, sb = (b - origin) / c;
      const unsigned int first = std::min<unsigned int>(static_cast<unsigned int>(sa), n - 1);
      const unsigned int last
        = std::max(first, std::min<unsigned int>(static_cast<unsigned int>(std::ceil(sb)), n) - 1);
      Assert(last - first + 2 <= max_reach, dealii::ExcInternalError());
      const unsigned int n_nodes = std::min(last - first + 2, max_reach);
      const double       scale   = 1. / (sb - sa);
      for (unsigned int k = 0; k < n_nodes; ++k)
        weights[k] = 0.;
      for (unsigned int k = 0; k + 1 < n_nodes; ++k)
        {
          const double left  = std::max(sa - (first + k), 0.);
          const double right = std::min(sb - (first + k), 1.);
          const double ramp  = 0.5 * (right * right - left * left);
          weights[k] += (right - left - ramp) * scale;
          weights[k + 1] += ramp * scale;
        }
      return {first, n_nodes};
    }



    void
    ColumnProjection::add_column(const dealii::Point<2> &x,
                                 const double            V,
                                 const double            m,
                                 const double            vx,
                                 const double            vy,
                                 const double            bx,
                                 const double            by)
    {
      // The rectangle, clipped to the domain [x0, x0 + nx c] x [y0, y0 + ny c].
      const double left   = std::max(x[0] - bx, corner[0]);
      const double right  = std::min(x[0] + bx, corner[0] + nx * c);
      const double bottom = std::max(x[1] - by, corner[1]);
      const double top    = std::min(x[1] + by, corner[1] + ny * c);
      if (!(right > left) || !(top > bottom))
        return;
      // S_ip = (1 / |R_p|) integral over R_p of N_i: the product of the hats' mean values
      // along x and along y, each computed once per column.
      double       wx[max_reach], wy[max_reach];
      const auto   x_nodes        = hat_weights(left, right, corner[0], nx, wx);
      const auto   y_nodes        = hat_weights(bottom, top, corner[1], ny, wy);
      const auto   i0             = x_nodes.first;
      const auto   j0             = y_nodes.first;
      const double values[n_sums] = {V, m, m * vx, m * vy};
      for (unsigned int b = 0; b < y_nodes.second; ++b)
        {
          if (!(wy[b] > 0.))
            continue;
          for (unsigned int a = 0; a < x_nodes.second; ++a)
            {
              const double w = wx[a] * wy[b];
              if (!(w > 0.))
                continue;
              const double weighted[n_sums]
                = {w * values[0], w * values[1], w * values[2], w * values[3]};
              add(i0 + a, j0 + b, weighted);
            }
        }
    }



    void
    ColumnProjection::gather_on_rank_zero()
    {
      const MPI_Comm     comm    = MPI_COMM_WORLD;
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      if (n_ranks == 1)
        return;
      const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(comm);
      // Each touched pixel as its index (a double holds integers up to 2^53 exactly) and
      // its four sums.
      std::vector<double> mine;
      if (rank != 0)
        {
          mine.reserve(touched.size() * (n_sums + 1));
          for (const std::uint64_t k : touched)
            {
              const double *s = sums.find(k % (nx + 1), k / (nx + 1));
              mine.push_back(static_cast<double>(k));
              mine.insert(mine.end(), s, s + n_sums);
            }
        }
      const int        count = mine.size();
      std::vector<int> counts(n_ranks), offsets(n_ranks + 1, 0);
      MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
      for (unsigned int r = 0; r < n_ranks; ++r)
        offsets[r + 1] = offsets[r] + counts[r];
      std::vector<double> all(rank == 0 ? offsets[n_ranks] : 0);
      MPI_Gatherv(mine.data(),
                  count,
                  MPI_DOUBLE,
                  all.data(),
                  counts.data(),
                  offsets.data(),
                  MPI_DOUBLE,
                  0,
                  comm);
      if (rank != 0)
        {
          // This rank's sums went to rank 0: cleared for the next projection.
          for (const std::uint64_t k : touched)
            std::fill_n(sums.at(k % (nx + 1), k / (nx + 1)), n_sums, 0.);
          touched.clear();
          return;
        }
      for (std::size_t e = 0; e < all.size(); e += n_sums + 1)
        {
          const auto k = static_cast<std::uint64_t>(all[e]);
          add(k % (nx + 1), k / (nx + 1), all.data() + e + 1);
        }
    }



    const std::vector<ColumnProjection::Pixel> &
    ColumnProjection::project(const particles::PointCloud &cloud)
    {
      pixels.clear();
      // In the grid's order (for_each_particle()): the same sums in a resumed run.
      cloud.for_each_particle([&](const auto &particle) {
        const auto   p = particle.get_properties();
        const double h = p[property::depth];
        if (!(h > 0.))
          return;
        // The column's area A_p = V_p / h_p, in the proportions of its GIMP domain
        // (lx, ly): half-sides s lx, s ly with 4 s^2 lx ly = A_p; at most 2 c each, so
        // that a column spread thin stays a few pixels wide.
        const double V  = p[property::volume];
        const double lx = p[property::domain_half_x], ly = p[property::domain_half_y];
        const double s = std::sqrt(V / h / (4. * lx * ly));
        add_column(particle.get_location(),
                   V,
                   p[property::mass],
                   p[property::velocity_x],
                   p[property::velocity_y],
                   std::min(s * lx, 2. * c),
                   std::min(s * ly, 2. * c));
      });
      gather_on_rank_zero();
      // Rank 0 (or the only rank): thickness and velocity of every touched pixel, its
      // sums cleared for the next projection.
      pixels.reserve(touched.size());
      for (const std::uint64_t k : touched)
        {
          const unsigned int i = k % (nx + 1), j = k / (nx + 1);
          double            *s = sums.at(i, j);
          const double       area
            = c * c * (i == 0 || i == nx ? 0.5 : 1.) * (j == 0 || j == ny ? 0.5 : 1.);
          pixels.push_back({k, s[0] / area, s[2] / s[1], s[3] / s[1]});
          std::fill_n(s, n_sums, 0.);
        }
      touched.clear();
      return pixels;
    }
  } // namespace depth_averaged
} // namespace slidewave
