#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fstream>
#include <slidewave/core/csv_rows.h>
#include <slidewave/core/input_error.h>

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

    std::string
    count_in_words(const unsigned int n)
    {
      return n == 2 ? "two" : n == 3 ? "three" : std::to_string(n);
    }
  } // namespace



  std::vector<CsvRow>
  read_csv_rows(const std::string &parameter,
                const std::string &filename,
                const unsigned int n_columns)
  {
    std::ifstream in(filename);
    if (!in)
      throw InputError(parameter, filename, "the name of a readable CSV file");

    std::vector<CsvRow> rows;
    std::string         line;
    unsigned int        line_number     = 0;
    bool                seen_first_line = false;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::string trimmed = dealii::Utilities::trim(line);
        if (trimmed.empty() || trimmed[0] == '#')
          continue;
        const auto fields = dealii::Utilities::split_string_list(trimmed, ',');
        CsvRow     row{line_number, std::vector<double>(fields.size())};
        bool       numeric = fields.size() == n_columns;
        for (unsigned int i = 0; numeric && i < fields.size(); ++i)
          numeric = parse_number(fields[i], row.values[i]);
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
                             "a CSV file of " + count_in_words(n_columns)
                               + " numeric columns (line " + std::to_string(line_number)
                               + " reads '" + trimmed + "')");
          }
        seen_first_line = true;
        rows.push_back(std::move(row));
      }
    return rows;
  }
} // namespace slidewave
