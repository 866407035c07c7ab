#ifndef slidewave_tests_unit_check_h
#define slidewave_tests_unit_check_h

#include <cstdio>
#include <slidewave/core/input_error.h>

// What every unit test prints for each of its checks, and the verdict at the end.
namespace unit_check
{
  inline bool all_passed = true;
  /** Whether this process prints (false on all but one rank of a parallel test). */
  inline bool print = true;

  /** Prints "  what: yes|no" and remembers a failure. */
  inline void
  check(const bool condition, const char *what)
  {
    if (print)
      std::printf("  %s: %s\n", what, condition ? "yes" : "no");
    all_passed = all_passed && condition;
  }

  /** Whether @p f throws an InputError; prints what the error says is allowed. */
  template <typename Function>
  bool
  refused(const Function &f)
  {
    try
      {
        f();
      }
    catch (const slidewave::InputError &e)
      {
        if (print)
          std::printf("    (%s)\n", e.allowed.c_str());
        return true;
      }
    return false;
  }

  /** Prints the verdict; the test's exit status. */
  inline int
  finish()
  {
    std::printf(all_passed ? "all checks passed\n" : "SOME CHECKS FAILED\n");
    return all_passed ? 0 : 1;
  }
} // namespace unit_check

#endif
