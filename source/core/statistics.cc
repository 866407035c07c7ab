#include <cmath>
#include <cstdio>
#include <slidewave/core/input_error.h>
#include <slidewave/core/statistics.h>
#include <stdexcept>

namespace slidewave
{
  void
  Statistics::open(const std::string &filename,
                   const bool         write_file,
                   std::ostream      *echo_stream,
                   const bool         append)
  {
    appending = append;
    if (write_file)
      {
        file.open(filename, append ? std::ios::app : std::ios::out);
        require_written(file, filename);
        name = filename;
        file.precision(12);
      }
    echo = echo_stream;
  }



  void
  Statistics::flush()
  {
    if (file.is_open())
      {
        file.flush();
        require_written(file, name);
      }
  }



  void
  Statistics::add_value(const std::string &column, const double value)
  {
    current_row.emplace_back(column, value);
  }



  void
  Statistics::end_row()
  {
    if (columns.empty())
      {
        for (const auto &entry : current_row)
          columns.push_back(entry.first);
        if (file.is_open() && !appending)
          {
            for (unsigned int c = 0; c < columns.size(); ++c)
              file << (c == 0 ? "" : ",") << columns[c];
            file << '\n';
          }
      }
    if (current_row.size() != columns.size())
      throw std::logic_error("Statistics: a row must fill the columns of the first row");

    last_row.resize(columns.size());
    for (unsigned int c = 0; c < columns.size(); ++c)
      {
        if (current_row[c].first != columns[c])
          throw std::logic_error("Statistics: column '" + current_row[c].first + "' where '"
                                 + columns[c] + "' was expected");
        last_row[c] = current_row[c].second;
      }

    if (file.is_open())
      {
        for (unsigned int c = 0; c < columns.size(); ++c)
          file << (c == 0 ? "" : ",") << last_row[c];
        file << '\n';
        flush();
      }

    if (echo != nullptr)
      {
        // Fixed precision, 9 significant digits: enough for numdiff's relative tolerance
        // of 1e-8 and independent of the number of ranks (all values are reduced first).
        char buffer[64];
        for (unsigned int c = 0; c < columns.size(); ++c)
          {
            const double v = last_row[c];
            if (v == std::floor(v) && std::abs(v) < 1e15)
              std::snprintf(buffer, sizeof(buffer), "%.0f", v);
            else
              std::snprintf(buffer, sizeof(buffer), "%.8e", v);
            *echo << (c == 0 ? "" : " ") << columns[c] << '=' << buffer;
          }
        *echo << '\n';
      }
    current_row.clear();
  }



  double
  Statistics::last_value(const std::string &column) const
  {
    for (unsigned int c = 0; c < columns.size(); ++c)
      if (columns[c] == column)
        return last_row[c];
    throw std::logic_error("Statistics: no column '" + column + "'");
  }
} // namespace slidewave
