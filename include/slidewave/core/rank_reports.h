#ifndef slidewave_core_rank_reports_h
#define slidewave_core_rank_reports_h

#include <string>

namespace slidewave
{
  /**
   * Reports made by one rank and learned by all (collective): what the guards say about a
   * bad point, which point is the fastest.
   */
  namespace rank_reports
  {
    /** The report of the lowest rank whose @p local report is not empty, or "". */
    std::string
    first_nonempty(const std::string &local);

    /** The @p local report of the rank with the largest @p local_value (the lowest such
     *  rank on a tie). */
    std::string
    of_largest(double local_value, const std::string &local);
  } // namespace rank_reports
} // namespace slidewave

#endif
