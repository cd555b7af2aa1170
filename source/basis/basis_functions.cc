#include <impm/base/errors.h>
#include <impm/basis/basis_functions.h>

#include <stdexcept>

namespace impm
{
  namespace
  {
    /** The scene's names of the bases, in the order of BasisType. */
    const std::array<const char *, 2> names = {{"standard MPM", "GIMP"}};
  } // namespace



  BasisType
  basis_type_from_string(const std::string &name)
  {
    for (unsigned int b = 0; b < names.size(); ++b)
      if (name == names[b])
        return static_cast<BasisType>(b);
    throw InputError("Parameter 'Material points/Basis' = '" + name +
                     "' is not allowed: allowed: "
                     "standard MPM|GIMP.");
  }



  std::string
  basis_name(const BasisType basis)
  {
    return names[static_cast<unsigned int>(basis)];
  }
} // namespace impm
