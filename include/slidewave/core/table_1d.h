#ifndef slidewave_core_table_1d_h
#define slidewave_core_table_1d_h

#include <string>
#include <vector>

namespace slidewave
{
  /**
   * A function of one variable given as a two-column CSV table (x,y) and interpolated
   * linearly; constant beyond the first and last rows. Used for bed profiles B(x) and for
   * boundary time series q(t).
   *
   * File format: lines starting with '#' are comments; the first other line may be a header
   * whose fields are all non-numeric; every other line holds two numbers separated by a
   * comma. x must increase strictly. Anything else is an InputError naming @p parameter, the
   * file and the line.
   */
  class Table1D
  {
  public:
    Table1D(const std::string &parameter, const std::string &filename);

    double
    value(double x) const;

    const std::vector<double> &
    abscissae() const
    {
      return x;
    }

  private:
    std::vector<double> x;
    std::vector<double> y;
  };
} // namespace slidewave

#endif
