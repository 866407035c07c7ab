#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/table_1d.h>

namespace slidewave
{
  namespace
  {
    bool
    parse_number(const std::string &text, double &value)
    {
      const std::string trimmed = dealii::Utilities::trim(text);
      if (trimmed.empty())
        return false;
      try
        {
          std::size_t used = 0;
          value            = std::stod(trimmed, &used);
          return used == trimmed.size() && std::isfinite(value);
        }
      catch (const std::exception &)
        {
          return false;
        }
    }
  } // namespace



  Table1D::Table1D(const std::string &parameter, const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(parameter, filename, "the name of a readable CSV file");

    std::string  line;
    unsigned int line_number     = 0;
    bool         seen_first_line = false;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string trimmed = dealii::Utilities::trim(line);
        if (trimmed.empty() || trimmed[0] == '#')
          continue;
        const auto fields = dealii::Utilities::split_string_list(trimmed, ',');
        double     a = 0., b = 0.;
        const bool numeric
          = fields.size() == 2 && parse_number(fields[0], a) && parse_number(fields[1], b);
        if (!numeric)
          {
            const bool header
              = !seen_first_line
                && std::none_of(fields.begin(), fields.end(), [](const std::string &f) {
                     double dummy;
                     return parse_number(f, dummy);
                   });
            seen_first_line = true;
            if (header)
              continue;
            throw InputError(parameter,
                             filename,
                             "a CSV file of two numeric columns (line "
                               + std::to_string(line_number) + " reads '" + trimmed + "')");
          }
        seen_first_line = true;
        if (!x.empty() && !(a > x.back()))
          throw InputError(parameter,
                           filename,
                           "a CSV table whose first column increases strictly (line "
                             + std::to_string(line_number) + ": " + to_string(a) + " follows "
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
