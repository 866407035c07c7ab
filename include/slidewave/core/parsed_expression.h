#ifndef slidewave_core_parsed_expression_h
#define slidewave_core_parsed_expression_h

#include <deal.II/base/function_parser.h>
#include <memory>
#include <string>

namespace slidewave
{
  /**
   * A scalar expression of position x and time t typed by the user (muparser syntax, e.g.
   * "x < 0.5 ? 1.0 : 0.5"), with optional named constants ("h_l=1, h_r=0.5").
   *
   * A malformed expression or constant list is an InputError naming @p parameter, not a
   * deal.II exception. Evaluation is not cheap: use it to set up fields and boundary values,
   * never per cell per step.
   */
  class ParsedExpression
  {
  public:
    ParsedExpression(const std::string &parameter,
                     const std::string &expression,
                     const std::string &constants = "");

    double
    value(double x, double t = 0.) const;

  private:
    std::unique_ptr<dealii::FunctionParser<1>> function;
  };

  /**
   * Initializes @p function (as many components as ';'-separated expressions in
   * @p expression, variables @p variables, "t" last when @p time_dependent) and evaluates
   * it once at the origin (muparser compiles lazily); a wrong number of expressions or a
   * syntax error is an InputError naming @p parameter and @p allowed with
   * muparser's reason (deal.II's print of it to std::cerr is captured).
   */
  template <int dim>
  void
  initialize_parser(dealii::FunctionParser<dim> &function,
                    const std::string           &variables,
                    const std::string           &expression,
                    bool                         time_dependent,
                    const std::string           &parameter,
                    const std::string           &allowed);

  /** Parses "a=1, b=2" into a map, throwing an InputError naming @p parameter. */
  std::map<std::string, double>
  parse_constants(const std::string &parameter, const std::string &constants);
} // namespace slidewave

#endif
