#ifndef slidewave_core_input_error_h
#define slidewave_core_input_error_h

#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace slidewave
{
  /**
   * A mistake in what the user gave us: a parameter value that is out of range or
   * inconsistent, a missing file, an output directory that cannot be written.
   *
   * It carries the parameter (its full path, e.g. "Shallow water/Courant number"), the value
   * as the user wrote it and a description of what is allowed. The application turns it into
   * one line that also names the input file, and exits with status 1. It is never used for
   * programming errors: those stay deal.II assertions.
   */
  class InputError : public std::runtime_error
  {
  public:
    InputError(const std::string &parameter, const std::string &value, const std::string &allowed);

    /** The full path of the offending parameter, subsections separated by '/'. */
    const std::string parameter;
    /** The value as given (the message shows at most its first 120 characters when it is
     *  longer than 200). */
    const std::string value;
    /** What would have been accepted. */
    const std::string allowed;
  };

  /**
   * A run that became physically or numerically invalid (non-finite values, negative depth):
   * thrown by the run-time guards with the step, time and place, caught by the application,
   * which keeps the last good output and exits non-zero.
   */
  class RunFailure : public std::runtime_error
  {
  public:
    explicit RunFailure(const std::string &what);
  };

  /**
   * A file the run could not write (a full disk, a folder removed or made read-only during
   * the run, a GDAL driver that failed): the message names the file and the reason. The
   * application exits with status 2 like a RunFailure; the output written before is kept.
   */
  class OutputFailure : public std::runtime_error
  {
  public:
    /** "cannot write '<file>' (<reason>)". */
    OutputFailure(const std::string &file, const std::string &reason);
  };

  /**
   * Throws an OutputFailure naming @p file when @p stream has failed (after the writes, and
   * after close() for a file stream, whose buffer is written then); the reason is errno's.
   */
  void
  require_written(const std::ostream &stream, const std::string &file);

  /** Formats a double the way messages print values: shortest round-trip form. */
  std::string
  to_string(double value);

  /**
   * Check helpers used by the parse_parameters() functions. Each throws an InputError naming
   * @p parameter when the condition does not hold.
   */
  void
  require_positive(const std::string &parameter, double value);

  void
  require_non_negative(const std::string &parameter, double value);

  void
  require_in_range(const std::string &parameter,
                   double             value,
                   double             lower,
                   bool               lower_inclusive,
                   double             upper,
                   bool               upper_inclusive);

  /**
   * The comma-separated finite numbers of @p text. Throws InputError(@p parameter, @p text,
   * @p allowed) when an item is not a finite number or, if @p count > 0, when there are not
   * exactly @p count of them.
   */
  std::vector<double>
  parse_number_list(const std::string &parameter,
                    const std::string &text,
                    const std::string &allowed,
                    unsigned int       count = 0);
} // namespace slidewave

#endif
