#include <impm/base/plugin_list.h>

namespace impm
{
  std::vector<std::string> &
  plugin_registration_errors()
  {
    static std::vector<std::string> errors;
    return errors;
  }
} // namespace impm
