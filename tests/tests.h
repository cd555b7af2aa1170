#ifndef impm_tests_h
#define impm_tests_h

// Shared helpers for IMPM's unit tests. A unit test prints to standard
// output, which the deal.II test driver compares with NAME.output.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace impm_tests
{
  /**
   * @brief Print whether @p value is below @p limit, with the value rounded
   * to one significant digit's order of magnitude, so that round-off does
   * not change the text but a regression does.
   */
  inline void
  check_below(const std::string &what, const double value, const double limit)
  {
    std::cout << what << " below " << limit << ": "
              << ((std::isfinite(value) && value < limit) ? "yes" : "NO")
              << std::endl;
  }
} // namespace impm_tests

#endif
