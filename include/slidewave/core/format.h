#ifndef slidewave_core_format_h
#define slidewave_core_format_h

#include <cstdio>
#include <string>

namespace slidewave
{
  /** @p value printed with the printf @p pattern (one conversion), for reports. */
  inline std::string
  format(const char *pattern, const double value)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), pattern, value);
    return buffer;
  }
} // namespace slidewave

#endif
