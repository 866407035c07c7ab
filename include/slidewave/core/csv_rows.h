#ifndef slidewave_core_csv_rows_h
#define slidewave_core_csv_rows_h

#include <string>
#include <vector>

namespace slidewave
{
  /** One row of numbers of a CSV file and the line it came from. */
  struct CsvRow
  {
    unsigned int        line = 0;
    std::vector<double> values;
  };

  /**
   * The rows of a CSV file of @p n_columns numeric columns: lines starting with '#' and
   * empty lines are skipped; the first other line may be a header whose fields are all
   * non-numeric. A missing file, a row of another length or a field that is not a finite
   * number is an InputError naming @p parameter, the file and the line.
   */
  std::vector<CsvRow>
  read_csv_rows(const std::string &parameter, const std::string &filename, unsigned int n_columns);
} // namespace slidewave

#endif
