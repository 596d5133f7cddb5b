#ifndef bfemp_tests_format_h
#define bfemp_tests_format_h

// One number printed with a printf pattern, for .output lines whose
// precision the test states.

#include <cstdio>
#include <string>

namespace bfemp_tests
{
  inline std::string
  format(const char *pattern, const double value)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), pattern, value);
    return buffer;
  }
} // namespace bfemp_tests

#endif
