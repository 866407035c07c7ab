#include <cerrno>
#include <cmath>
#include <cstring>
#include <deal.II/base/utilities.h>
#include <slidewave/core/input_error.h>
#include <sstream>

namespace slidewave
{
  namespace
  {
    /** @p value as a message shows it: whole up to 200 characters, else its start and its
     *  length (a 10 MB expression is not echoed back). */
    std::string
    shown(const std::string &value)
    {
      constexpr std::size_t longest = 200;
      if (value.size() <= longest)
        return value;
      return value.substr(0, 120) + "... (" + std::to_string(value.size()) + " characters)";
    }
  } // namespace



  InputError::InputError(const std::string &parameter,
                         const std::string &value,
                         const std::string &allowed)
    : std::runtime_error("parameter '" + shown(parameter) + "' = '" + shown(value)
                         + "': allowed: " + allowed)
    , parameter(parameter)
    , value(value)
    , allowed(allowed)
  {
  }



  RunFailure::RunFailure(const std::string &what)
    : std::runtime_error(what)
  {
  }



  OutputFailure::OutputFailure(const std::string &file, const std::string &reason)
    : std::runtime_error("cannot write '" + file + "' (" + reason + ")")
  {
  }



  void
  require_written(const std::ostream &stream, const std::string &file)
  {
    if (stream.fail())
      throw OutputFailure(file,
                          errno != 0 ? std::string(std::strerror(errno)) :
                                       std::string("the stream failed"));
  }



  std::string
  to_string(const double value)
  {
    std::ostringstream out;
    out.precision(15);
    out << value;
    return out.str();
  }



  void
  require_positive(const std::string &parameter, const double value)
  {
    if (!(value > 0.) || !std::isfinite(value))
      throw InputError(parameter, to_string(value), "a finite number > 0");
  }



  void
  require_non_negative(const std::string &parameter, const double value)
  {
    if (!(value >= 0.) || !std::isfinite(value))
      throw InputError(parameter, to_string(value), "a finite number >= 0");
  }



  void
  require_in_range(const std::string &parameter,
                   const double       value,
                   const double       lower,
                   const bool         lower_inclusive,
                   const double       upper,
                   const bool         upper_inclusive)
  {
    const bool above = lower_inclusive ? value >= lower : value > lower;
    const bool below = upper_inclusive ? value <= upper : value < upper;
    if (!(above && below) || !std::isfinite(value))
      throw InputError(parameter,
                       to_string(value),
                       "a number in " + std::string(lower_inclusive ? "[" : "(") + to_string(lower)
                         + ", " + to_string(upper) + (upper_inclusive ? "]" : ")"));
  }



  std::vector<double>
  parse_number_list(const std::string &parameter,
                    const std::string &text,
                    const std::string &allowed,
                    const unsigned int count)
  {
    std::vector<double> values;
    for (const std::string &item : dealii::Utilities::split_string_list(text, ','))
      {
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(item, &used);
            if (used != item.size() || !std::isfinite(value))
              throw std::invalid_argument("");
            values.push_back(value);
          }
        catch (const std::exception &)
          {
            throw InputError(parameter, text, allowed);
          }
      }
    if (count > 0 && values.size() != count)
      throw InputError(parameter, text, allowed);
    return values;
  }
} // namespace slidewave
