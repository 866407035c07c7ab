#ifndef slidewave_core_statistics_h
#define slidewave_core_statistics_h

#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace slidewave
{
  /**
   * The monitored quantities of a run: one row per reported step, one column per quantity
   * (time, step, dt, and what each physics adds). Written to `statistics.csv` as rows
   * complete, so that a run that stops early keeps what it had. The columns are fixed by the
   * first row; every later row must fill the same columns in the same order.
   *
   * In test mode the rows are also echoed to a stream at fixed precision, which is what the
   * regression tests compare.
   */
  class Statistics
  {
  public:
    /**
     * Opens @p filename for writing when @p write_file is true (rank 0); other ranks keep
     * the values but write nothing. Rows are echoed to @p echo when it is not null.
     */
    void
    open(const std::string &filename, bool write_file, std::ostream *echo, bool append = false);

    /** Writes what is buffered to the file. */
    void
    flush();

    /** Sets the value of @p column in the current row. */
    void
    add_value(const std::string &column, double value);

    /** Ends the current row: writes it and starts a new one. */
    void
    end_row();

    /** The value of @p column in the last completed row. */
    double
    last_value(const std::string &column) const;

  private:
    std::vector<std::string>                    columns;
    std::vector<std::pair<std::string, double>> current_row;
    std::vector<double>                         last_row;
    std::ofstream                               file;
    /** The file's name, for the message of a failed write. */
    std::string   name;
    std::ostream *echo = nullptr;
    /** Appending to an existing file: its header is there already. */
    bool appending = false;
  };
} // namespace slidewave

#endif
