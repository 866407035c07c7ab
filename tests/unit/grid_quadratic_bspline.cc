// The quadratic B-spline basis of grid::QuadraticBSpline (paper 002, Appendix A) on
// [-0.75, 1.25] cut into 8 cells (h = 0.25), at 801 points and at every knot:
//   1. partition of unity and non-negativity; the derivatives sum to zero;
//   2. linear completeness: sum N_i(x) c_i = x and sum N'_i(x) c_i = 1 with the control
//      points c_i (Greville abscissae);
//   3. away from the ends (the functions whose knots are all distinct) each function is the
//      uniform quadratic B-spline 3/4 - s^2 (|s| <= 1/2), (3/2 - |s|)^2 / 2 (1/2 <= |s| <=
//      3/2), s = (x - centre) / h, and its derivative;
//   4. C^1: at every interior knot the values and derivatives seen from the cell on its
//      left (x = knot - eps) and on its right (x = knot + eps) agree (to O(eps / h));
//   5. interpolation at the ends: N_0(a) = 1, N_{n+1}(b) = 1;
//   6. the derivatives against central differences of the values (step 1e-6 h).
// Values, derivatives times h and coordinates over h are of order one and computed in a few
// operations: 1e-13 is round-off for 1-3 and 5; 4 compares across 2 eps = 2e-10 h, a smooth
// function changes by about 1e-9 there (tolerance 1e-8); 6 has a truncation error of order
// (1e-6)^2 and a cancellation error of order 1e-16 / 1e-6 = 1e-10 (tolerance 1e-8). Exits
// non-zero on failure.
#include "unit_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <slidewave/grid/quadratic_bspline.h>

using namespace slidewave::grid;
using unit_check::check;

namespace
{
  double
  uniform_bspline(const double s)
  {
    const double r = std::abs(s);
    return r <= 0.5 ? 0.75 - s * s : (r <= 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0.);
  }

  double
  uniform_bspline_derivative(const double s)
  {
    const double r = std::abs(s);
    return r <= 0.5 ? -2. * s : (r <= 1.5 ? -(1.5 - r) * (s > 0. ? 1. : -1.) : 0.);
  }
} // namespace

int
main()
{
  const double           a = -0.75, b = 1.25;
  const unsigned int     n = 8;
  const double           h = (b - a) / n;
  const QuadraticBSpline basis(a, b, n);
  std::printf(
    "quadratic B-splines on [%g, %g], %u cells, %u functions\n", a, b, n, basis.n_functions());
  std::printf("  control points:");
  for (unsigned int i = 0; i < basis.n_functions(); ++i)
    std::printf(" %g", basis.control_point(i));
  std::printf("\n");

  std::array<double, 3> values, derivatives;
  double unity = 0., negative = 0., derivative_sum = 0., linear = 0., linear_derivative = 0.,
         interior = 0., fd = 0.;
  const unsigned int samples = 801;
  for (unsigned int k = 0; k < samples; ++k)
    {
      const double x = a + (b - a) * k / (samples - 1.);
      basis.evaluate(x, values, derivatives);
      const unsigned int c   = basis.cell(x);
      double             sum = 0., dsum = 0., lin = 0., dlin = 0.;
      for (unsigned int j = 0; j < 3; ++j)
        {
          const unsigned int i = c + j;
          sum += values[j];
          dsum += derivatives[j];
          lin += values[j] * basis.control_point(i);
          dlin += derivatives[j] * basis.control_point(i);
          negative = std::max(negative, -values[j]);
          // Functions 2 ... n - 1 have distinct knots: the uniform B-spline centred at the
          // middle of their support [a + (i - 2) h, a + (i + 1) h].
          if (i >= 2 && i + 1 <= n)
            {
              const double centre = a + (i - 0.5) * h;
              const double s      = (x - centre) / h;
              interior            = std::max({interior,
                                              std::abs(values[j] - uniform_bspline(s)),
                                              std::abs(derivatives[j] * h - uniform_bspline_derivative(s))});
            }
          // Central differences inside the cell (the two neighbours in the same cell).
          const double step = 1e-6 * h;
          if (x - step >= a + c * h && x + step <= a + (c + 1) * h)
            {
              std::array<double, 3> vp, vm, unused;
              basis.evaluate(x + step, vp, unused);
              basis.evaluate(x - step, vm, unused);
              if (basis.cell(x + step) == c && basis.cell(x - step) == c)
                fd = std::max(fd, std::abs((vp[j] - vm[j]) / (2. * step) - derivatives[j]) * h);
            }
        }
      unity             = std::max(unity, std::abs(sum - 1.));
      derivative_sum    = std::max(derivative_sum, std::abs(dsum) * h);
      linear            = std::max(linear, std::abs(lin - x) / h);
      linear_derivative = std::max(linear_derivative, std::abs(dlin - 1.));
    }
  std::printf("  largest |sum N - 1| = %.1e, largest -N = %.1e, largest |sum N'| h = %.1e\n",
              unity,
              negative,
              derivative_sum);
  check(unity < 1e-13 && negative <= 0. && derivative_sum < 1e-13,
        "partition of unity, non-negative, derivatives sum to zero (1e-13)");
  std::printf("  largest |sum N c - x| / h = %.1e, |sum N' c - 1| = %.1e\n",
              linear,
              linear_derivative);
  check(linear < 1e-13 && linear_derivative < 1e-13, "linear completeness (1e-13)");
  std::printf("  interior functions against the uniform B-spline: %.1e\n", interior);
  check(interior < 1e-13, "interior functions are the uniform quadratic B-spline (1e-13)");
  std::printf("  derivatives against central differences: %.1e\n", fd);
  check(fd < 1e-8, "derivatives equal central differences (1e-8)");

  // C^1 across the interior knots: the full basis from both sides.
  double jump = 0., jump_derivative = 0.;
  for (unsigned int k = 1; k < n; ++k)
    {
      const double          x = a + k * h, eps = 1e-10 * h;
      std::array<double, 3> vl, dl, vr, dr;
      basis.evaluate(x - eps, vl, dl);
      basis.evaluate(x + eps, vr, dr);
      const unsigned int cl = basis.cell(x - eps), cr = basis.cell(x + eps);
      for (unsigned int i = 0; i < basis.n_functions(); ++i)
        {
          const auto pick = [&](const std::array<double, 3> &v, const unsigned int c) {
            return i >= c && i < c + 3 ? v[i - c] : 0.;
          };
          jump            = std::max(jump, std::abs(pick(vl, cl) - pick(vr, cr)));
          jump_derivative = std::max(jump_derivative, std::abs(pick(dl, cl) - pick(dr, cr)) * h);
        }
    }
  std::printf("  largest jump at interior knots: values %.1e, derivatives x h %.1e\n",
              jump,
              jump_derivative);
  check(jump < 1e-8 && jump_derivative < 1e-8, "C1 across interior knots (1e-8)");

  basis.evaluate(a, values, derivatives);
  const double first = values[0];
  basis.evaluate(b, values, derivatives);
  const double last = values[2];
  std::printf("  N_0(a) = %.15g, N_%u(b) = %.15g\n", first, basis.n_functions() - 1, last);
  check(std::abs(first - 1.) < 1e-13 && std::abs(last - 1.) < 1e-13,
        "interpolation at both ends (1e-13)");
  return unit_check::finish();
}
