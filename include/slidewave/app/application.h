#ifndef slidewave_app_application_h
#define slidewave_app_application_h

#include <deal.II/base/parameter_handler.h>
#include <ostream>
#include <string>
#include <vector>

namespace slidewave
{
  /** Exit statuses of the program. */
  enum ExitStatus : int
  {
    success            = 0,
    input_error        = 1, ///< bad command line or scene file; nothing was run
    run_failure        = 2, ///< the run became invalid (non-finite, negative depth)
    verification_error = 3  ///< the error against an exact solution exceeded its tolerance
  };

  /** Declares the parameters of every component of every physics. */
  void
  declare_all_parameters(dealii::ParameterHandler &prm);

  /**
   * The whole program behind the `slidewave` executable, minus MPI initialization (the
   * caller owns it): parses the command line @p arguments (without the program name), reads
   * and checks the scene, and runs it. Messages go to @p out and @p err on rank 0 only.
   * Returns an ExitStatus.
   */
  int
  run_application(const std::vector<std::string> &arguments, std::ostream &out, std::ostream &err);
} // namespace slidewave

#endif
