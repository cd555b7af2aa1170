#ifndef impm_base_quiet_call_h
#define impm_base_quiet_call_h

#include <functional>

namespace impm
{
  /**
   * @brief Run @p action with std::cerr silenced; whether it ended without
   * an exception. For deal.II's FunctionParser, whose muparser finds an
   * expression's syntax errors only at its first evaluation and writes
   * them to std::cerr before throwing: a caller evaluates once through
   * this and reports a bad expression in one line of its own.
   */
  bool
  quiet_call(const std::function<void()> &action);
} // namespace impm

#endif
