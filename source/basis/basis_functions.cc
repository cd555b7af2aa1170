#include <impm/basis/basis_functions.h>

namespace impm
{
  BasisType
  basis_type_from_string(const std::string &name)
  {
    if (name == "standard MPM")
      return BasisType::standard_mpm;
    AssertThrow(name == "GIMP",
                ExcMessage("Parameter 'Basis' = '" + name +
                           "' is not known; allowed: standard MPM|GIMP"));
    return BasisType::gimp;
  }
} // namespace impm
