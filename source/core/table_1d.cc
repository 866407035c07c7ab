#include <algorithm>
#include <slidewave/core/csv_rows.h>
#include <slidewave/core/input_error.h>
#include <slidewave/core/table_1d.h>

namespace slidewave
{
  Table1D::Table1D(const std::string &parameter, const std::string &filename)
  {
    for (const auto &row : read_csv_rows(parameter, filename, 2))
      {
        const double a = row.values[0], b = row.values[1];
        if (!x.empty() && !(a > x.back()))
          throw InputError(parameter,
                           filename,
                           "a CSV table whose first column increases strictly (line "
                             + std::to_string(row.line) + ": " + to_string(a) + " follows "
                             + to_string(x.back()) + ")");
        x.push_back(a);
        y.push_back(b);
      }
    if (x.empty())
      throw InputError(parameter, filename, "a CSV table with at least one row x,y");
  }



  double
  Table1D::value(const double at) const
  {
    if (at <= x.front())
      return y.front();
    if (at >= x.back())
      return y.back();
    const auto   upper = std::upper_bound(x.begin(), x.end(), at);
    const auto   i     = static_cast<std::size_t>(upper - x.begin());
    const double w     = (at - x[i - 1]) / (x[i] - x[i - 1]);
    return (1. - w) * y[i - 1] + w * y[i];
  }
} // namespace slidewave
