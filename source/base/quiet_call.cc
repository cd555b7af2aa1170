// Running an action with std::cerr silenced (muparser's first evaluation).
#include <impm/base/quiet_call.h>

#include <iostream>
#include <sstream>

namespace impm
{
  bool
  quiet_call(const std::function<void()> &action)
  {
    std::ostringstream discarded;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(discarded.rdbuf());
    bool               succeeded   = true;
    try
      {
        action();
      }
    catch (...)
      {
        succeeded = false;
      }
    std::cerr.rdbuf(cerr_buffer);
    return succeeded;
  }
} // namespace impm
