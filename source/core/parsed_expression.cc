#include <algorithm>
#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>
#include <iostream>
#include <slidewave/core/input_error.h>
#include <slidewave/core/parsed_expression.h>
#include <sstream>

namespace slidewave
{
  namespace
  {
    /** muparser's reason in deal.II's diagnosis @p text, as " (muparser: ...)". */
    std::string
    muparser_reason(const std::string &text)
    {
      const auto at = text.find("Message:");
      if (at == std::string::npos)
        return "";
      const auto open  = text.find('<', at);
      const auto close = text.find('>', open);
      if (open == std::string::npos || close == std::string::npos)
        return "";
      return " (muparser: " + text.substr(open + 1, std::min<std::size_t>(close - open - 1, 200))
             + ")";
    }
  } // namespace



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
        throw InputError(parameter,
                         expression,
                         "a valid expression of x and t in muparser syntax, e.g. "
                         "'x < 0.5 ? 1.0 : 0.5', using only the declared constants"
                           + muparser_reason(diagnosis.str()));
      }
  }



  template <int dim>
  void
  initialize_parser(dealii::FunctionParser<dim> &function,
                    const std::string           &variables,
                    const std::string           &expression,
                    const bool                   time_dependent,
                    const std::string           &parameter,
                    const std::string           &allowed)
  {
    if (static_cast<unsigned int>(std::count(expression.begin(), expression.end(), ';') + 1)
        != function.n_components)
      throw InputError(parameter, expression, allowed);
    std::ostringstream diagnosis;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(diagnosis.rdbuf());
    try
      {
        function.initialize(variables, expression, {}, time_dependent);
        // muparser compiles lazily: evaluate once so that syntax errors surface here.
        for (unsigned int c = 0; c < function.n_components; ++c)
          (void)function.value(dealii::Point<dim>(), c);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (...)
      {
        std::cerr.rdbuf(cerr_buffer);
        throw InputError(parameter, expression, allowed + muparser_reason(diagnosis.str()));
      }
  }

  template void
  initialize_parser(dealii::FunctionParser<1> &,
                    const std::string &,
                    const std::string &,
                    bool,
                    const std::string &,
                    const std::string &);
  template void
  initialize_parser(dealii::FunctionParser<2> &,
                    const std::string &,
                    const std::string &,
                    bool,
                    const std::string &,
                    const std::string &);



  double
  ParsedExpression::value(const double x, const double t) const
  {
    function->set_time(t);
    return function->value(dealii::Point<1>(x));
  }
} // namespace slidewave
