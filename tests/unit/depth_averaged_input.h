#ifndef slidewave_tests_depth_averaged_input_h
#define slidewave_tests_depth_averaged_input_h

#include <deal.II/base/parameter_handler.h>
#include <slidewave/depth_averaged/depth_averaged_parameters.h>
#include <string>

// The parameters of a depth-averaged scene written in the test itself.
namespace
{
  /** The "Depth averaged" subsection of @p input (a scene's text, "subsection Depth
   *  averaged ... end"), declared, read and checked as the program does. */
  slidewave::depth_averaged::DepthAveragedParameters
  depth_averaged_parameters(const std::string &input)
  {
    dealii::ParameterHandler prm;
    prm.enter_subsection("Depth averaged");
    slidewave::depth_averaged::DepthAveragedParameters::declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string(input);
    slidewave::depth_averaged::DepthAveragedParameters parameters;
    prm.enter_subsection("Depth averaged");
    parameters.parse_parameters(prm, "Depth averaged");
    prm.leave_subsection();
    return parameters;
  }
} // namespace

#endif
