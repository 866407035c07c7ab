#include <algorithm>
#include <cmath>
#include <slidewave/grid/quadratic_bspline.h>
#include <stdexcept>

namespace slidewave
{
  namespace grid
  {
    QuadraticBSpline::QuadraticBSpline(const double a, const double b, const unsigned int n_cells)
      : a(a)
      , h((b - a) / n_cells)
      , n_cells(n_cells)
    {
      if (n_cells < 1 || !(b > a))
        throw std::invalid_argument("QuadraticBSpline: needs b > a and at least one cell");
    }



    double
    QuadraticBSpline::knot(const unsigned int k) const
    {
      // {a, a, a, a + h, ..., a + (n - 1) h, b, b, b}: knot k sits at a + (k - 2) h,
      // clamped to the ends.
      const int position = std::clamp(static_cast<int>(k) - 2, 0, static_cast<int>(n_cells));
      return a + position * h;
    }



    unsigned int
    QuadraticBSpline::cell(const double x) const
    {
      const double c = std::floor((x - a) / h);
      return static_cast<unsigned int>(std::clamp(c, 0., static_cast<double>(n_cells - 1)));
    }



    void
    QuadraticBSpline::evaluate(const double           x,
                               std::array<double, 3> &values,
                               std::array<double, 3> &derivatives) const
    {
      // Cell c spans knots c + 2 and c + 3; the degree-0 function nonzero there is
      // N_{c+2,0}. The recursion raises the degree over the functions that overlap it:
      // degree 1: N_{c+1,1}, N_{c+2,1}; degree 2: N_{c,2}, N_{c+1,2}, N_{c+2,2}.
      const unsigned int c     = cell(x);
      const auto         ratio = [](const double numerator, const double denominator) {
        return denominator > 0. ? numerator / denominator : 0.; // 0/0 = 0 at repeated knots
      };
      const auto xi = [&](const unsigned int k) { return knot(k); };
      // Degree 1, functions c + 1 and c + 2 (N_{c+2,0} = 1, the others 0 in this cell).
      const double n1_first  = ratio(xi(c + 3) - x, xi(c + 3) - xi(c + 2)); // N_{c+1,1}
      const double n1_second = ratio(x - xi(c + 2), xi(c + 3) - xi(c + 2)); // N_{c+2,1}
      // Degree 2, functions c, c + 1, c + 2.
      values[0] = ratio(xi(c + 3) - x, xi(c + 3) - xi(c + 1)) * n1_first;
      values[1] = ratio(x - xi(c + 1), xi(c + 3) - xi(c + 1)) * n1_first
                  + ratio(xi(c + 4) - x, xi(c + 4) - xi(c + 2)) * n1_second;
      values[2] = ratio(x - xi(c + 2), xi(c + 4) - xi(c + 2)) * n1_second;
      // N'_{i,2} = 2 (N_{i,1} / (xi_{i+2} - xi_i) - N_{i+1,1} / (xi_{i+3} - xi_{i+1})).
      derivatives[0] = 2. * (0. - ratio(n1_first, xi(c + 3) - xi(c + 1)));
      derivatives[1]
        = 2. * (ratio(n1_first, xi(c + 3) - xi(c + 1)) - ratio(n1_second, xi(c + 4) - xi(c + 2)));
      derivatives[2] = 2. * (ratio(n1_second, xi(c + 4) - xi(c + 2)) - 0.);
    }



    double
    QuadraticBSpline::control_point(const unsigned int i) const
    {
      return 0.5 * (knot(i + 1) + knot(i + 2));
    }
  } // namespace grid
} // namespace slidewave
