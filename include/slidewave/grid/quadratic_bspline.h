#ifndef slidewave_grid_quadratic_bspline_h
#define slidewave_grid_quadratic_bspline_h

#include <array>
#include <vector>

namespace slidewave
{
  namespace grid
  {
    /**
     * The quadratic B-spline basis of one grid direction (paper 002, Appendix A): the
     * interval [a, b] cut into n uniform cells of width h, the open knot vector
     * {a, a, a, a + h, ..., b - h, b, b, b} (end knots repeated p + 1 = 3 times, so the
     * basis interpolates at both ends), n + 2 basis functions N_0 ... N_{n+1} built by the
     * Cox-de Boor recursion
     *
     *   N_{i,0}(x) = 1 on [xi_i, xi_{i+1}), 0 elsewhere,
     *   N_{i,p}(x) = (x - xi_i) / (xi_{i+p} - xi_i) N_{i,p-1}(x)
     *              + (xi_{i+p+1} - x) / (xi_{i+p+1} - xi_{i+1}) N_{i+1,p-1}(x)   (0/0 = 0),
     *
     * and their derivatives N'_{i,2} = 2 (N_{i,1} / (xi_{i+2} - xi_i) - N_{i+1,1} /
     * (xi_{i+3} - xi_{i+1})). Each is C^1 (C^0 only at the repeated end knots), non-negative,
     * and they sum to one everywhere on [a, b]; away from the ends they are the translates of
     * the uniform quadratic B-spline (3/4 - s^2 for |s| <= 1/2, (3/2 - |s|)^2 / 2 for
     * 1/2 <= |s| <= 3/2, s = (x - c_i) / h about the centre c_i of the function's support).
     * The basis functions belong to control points (n + 2 of them, at the Greville abscissae
     * (xi_{i+1} + xi_{i+2}) / 2: a, a + h/2, a + 3h/2, ..., b - h/2, b), not to the grid's
     * n + 1 nodes: a material point method on them keeps its nodal fields at those points.
     * A point in cell c (x in [a + c h, a + (c + 1) h)) sees the three functions c, c + 1,
     * c + 2.
     */
    class QuadraticBSpline
    {
    public:
      /** The basis of [@p a, @p b] cut into @p n_cells >= 1 uniform cells. */
      QuadraticBSpline(double a, double b, unsigned int n_cells);

      /** n_cells + 2. */
      unsigned int
      n_functions() const
      {
        return n_cells + 2;
      }

      /** The cell of @p x (the last cell for x = b; x must lie in [a, b]). */
      unsigned int
      cell(double x) const;

      /** The values and derivatives at @p x of the three functions nonzero in its cell,
       *  cell(x), cell(x) + 1, cell(x) + 2. */
      void
      evaluate(double x, std::array<double, 3> &values, std::array<double, 3> &derivatives) const;

      /** The Greville abscissa of function @p i (its control point). */
      double
      control_point(unsigned int i) const;

      /** Knot @p k of the open knot vector (k = 0 ... n_cells + 4). */
      double
      knot(unsigned int k) const;

    private:
      double       a, h;
      unsigned int n_cells;
    };
  } // namespace grid
} // namespace slidewave

#endif
