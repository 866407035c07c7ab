#ifndef slidewave_core_parameter_documentation_h
#define slidewave_core_parameter_documentation_h

#include <deal.II/base/parameter_handler.h>
#include <ostream>

namespace slidewave
{
  /**
   * Writes every declared parameter as a Markdown reference: one section per subsection, one
   * entry per parameter with its default, what is allowed and its documentation. This is
   * what `slidewave --print-parameters markdown` prints and what doc/parameters.md holds.
   */
  void
  print_parameters_markdown(const dealii::ParameterHandler &prm, std::ostream &out);
} // namespace slidewave

#endif
