#include <algorithm>
#include <cmath>
#include <slidewave/core/csv_rows.h>
#include <slidewave/core/input_error.h>
#include <slidewave/terrain/earth_bounds.h>
#include <slidewave/terrain/elevation_table.h>
#include <vector>

namespace slidewave
{
  namespace terrain
  {
    namespace
    {
      /** The distinct values of @p v, sorted (equal to 1e-9 of the range). */
      std::vector<double>
      distinct(std::vector<double> v)
      {
        std::sort(v.begin(), v.end());
        const double tolerance = 1e-9 * (v.back() - v.front() + 1.);
        v.erase(std::unique(v.begin(),
                            v.end(),
                            [tolerance](const double a, const double b) {
                              return std::abs(a - b) <= tolerance;
                            }),
                v.end());
        return v;
      }

      /** The index of @p value on the lattice origin + k spacing, or -1 off the lattice. */
      long
      lattice_index(const double value, const double origin, const double spacing, const unsigned n)
      {
        const double k = (value - origin) / spacing;
        const long   i = std::lround(k);
        return (std::abs(k - i) <= 1e-6 && i >= 0 && i < static_cast<long>(n)) ? i : -1;
      }
    } // namespace



    ElevationGrid
    read_elevation_table(const std::string &parameter, const std::string &filename)
    {
      const auto rows = read_csv_rows(parameter, filename, 3);
      if (rows.size() < 4)
        throw InputError(parameter,
                         filename,
                         "a CSV table x,y,z of the nodes of a regular grid of at least 2 x 2 "
                         "nodes (it has "
                           + std::to_string(rows.size()) + " rows)");
      std::vector<double> xs, ys;
      for (const auto &row : rows)
        {
          xs.push_back(row.values[0]);
          ys.push_back(row.values[1]);
        }
      const auto         x = distinct(xs), y = distinct(ys);
      const unsigned int nx = x.size(), ny = y.size();
      if (nx < 2 || ny < 2)
        throw InputError(parameter, filename, "a grid of at least 2 x 2 nodes");
      const double dx = (x.back() - x.front()) / (nx - 1), dy = (y.back() - y.front()) / (ny - 1);
      for (unsigned int i = 0; i < nx; ++i)
        if (std::abs(x[i] - (x.front() + i * dx)) > 1e-6 * dx)
          throw InputError(parameter,
                           filename,
                           "nodes at equal spacings in x (x = " + to_string(x[i])
                             + " is not on the lattice of spacing " + to_string(dx) + ")");
      for (unsigned int j = 0; j < ny; ++j)
        if (std::abs(y[j] - (y.front() + j * dy)) > 1e-6 * dy)
          throw InputError(parameter,
                           filename,
                           "nodes at equal spacings in y (y = " + to_string(y[j])
                             + " is not on the lattice of spacing " + to_string(dy) + ")");
      if (rows.size() != static_cast<std::size_t>(nx) * ny)
        throw InputError(parameter,
                         filename,
                         "every node of the " + std::to_string(nx) + " x " + std::to_string(ny)
                           + " grid exactly once (the file has " + std::to_string(rows.size())
                           + " rows)");
      std::vector<double> z(static_cast<std::size_t>(nx) * ny, std::nan(""));
      for (const auto &row : rows)
        {
          const long i = lattice_index(row.values[0], x.front(), dx, nx);
          const long j = lattice_index(row.values[1], y.front(), dy, ny);
          if (i < 0 || j < 0)
            throw InputError(parameter,
                             filename,
                             "nodes of a regular grid (line " + std::to_string(row.line)
                               + " is off the lattice)");
          double &slot = z[static_cast<std::size_t>(j) * nx + i];
          if (!std::isnan(slot))
            throw InputError(parameter,
                             filename,
                             "every node once (line " + std::to_string(row.line) + " repeats ("
                               + to_string(row.values[0]) + ", " + to_string(row.values[1]) + "))");
          check_elevation(parameter, filename, row.values[0], row.values[1], row.values[2]);
          slot = row.values[2];
        }
      return ElevationGrid(dealii::Point<2>(x.front(), y.front()), dx, dy, nx, ny, std::move(z));
    }
  } // namespace terrain
} // namespace slidewave
