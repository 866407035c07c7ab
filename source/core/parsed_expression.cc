#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <sstream>

namespace slidewave
{
  std::map<std::string, double>
  parse_constants(const std::string &parameter, const std::string &constants)
  {
    std::map<std::string, double> result;
    for (const std::string &item : dealii::Utilities::split_string_list(constants, ','))
      {
        if (item.empty())
          continue;
        const auto equal = item.find('=');
        if (equal == std::string::npos)
          throw InputError(parameter, constants, "a comma-separated list of name=value pairs");
        const std::string name = dealii::Utilities::trim(item.substr(0, equal));
        const std::string text = dealii::Utilities::trim(item.substr(equal + 1));
        try
          {
            std::size_t  used  = 0;
            const double value = std::stod(text, &used);
            if (used != text.size() || name.empty())
              throw std::invalid_argument("trailing characters");
            result[name] = value;
          }
        catch (const std::exception &)
          {
            throw InputError(parameter,
                             constants,
                             "a comma-separated list of name=value pairs with numeric values");
          }
      }
    return result;
  }



  ParsedExpression::ParsedExpression(const std::string &parameter,
                                     const std::string &expression,
                                     const std::string &constants)
    : function(std::make_unique<dealii::FunctionParser<1>>(1))
  {
    const auto constant_map = parse_constants(parameter + " constants", constants);
    if (dealii::Utilities::trim(expression).empty())
      throw InputError(parameter, expression, "a non-empty expression of x and t");
    // deal.II prints muparser's diagnosis to std::cerr (once per rank) before it throws:
    // capture it, so that the user gets one line, with muparser's reason in it.
    std::ostringstream diagnosis;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
    try
      {
        function->initialize("x,t", expression, constant_map, /*time_dependent=*/true);
        // muparser compiles lazily: evaluate once so that syntax errors surface here,
        // at parse time, and not in the middle of a run.
        const double probe = value(0., 0.);
        (void)probe;
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (...)
      {
        std::cerr.rdbuf(cerr_buffer);
        std::string       reason;
        const std::string text = diagnosis.str();
        const auto        at   = text.find("Message:");
        if (at != std::string::npos)
          {
            const auto open  = text.find('<', at);
            const auto close = text.find('>', open);
            if (open != std::string::npos && close != std::string::npos)
              reason = " (muparser: " + text.substr(open + 1, close - open - 1) + ")";
          }
        throw InputError(parameter,
                         expression,
                         "a valid expression of x and t in muparser syntax, e.g. "
                         "'x < 0.5 ? 1.0 : 0.5', using only the declared constants"
                           + reason);
      }
  }



  double
  ParsedExpression::value(const double x, const double t) const
  {
    function->set_time(t);
    return function->value(dealii::Point<1>(x));
  }
} // namespace slidewave
