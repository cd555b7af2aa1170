// A material plugin for IMPM: Hencky elasticity registered under a name of
// its own, "plugin elastic", with its own description. A scene that loads
// this library (Additional shared libraries) may set
//   subsection Body 1
//     subsection Material
//       set Model = plugin elastic
//       subsection plugin elastic
//         set Young's modulus = 1e6
//       end
//     end
//   end
// and gets the same numbers as with the built-in model "Hencky elastic".

#include <impm/mechanics/material.h>

#include <limits>
#include <memory>
#include <sstream>
#include <string>

namespace plugin_example
{
  using namespace dealii;

  /**
   * @brief Hencky elasticity (IMPM's HenckyVonMises without a yield
   * stress) under another name.
   */
  class PluginElastic : public impm::HenckyVonMises
  {
  public:
    /** @brief Young's modulus @p E and Poisson's ratio @p nu. */
    PluginElastic(const double E, const double nu)
      : impm::HenckyVonMises(E, nu, std::numeric_limits<double>::infinity())
      , E(E)
      , nu(nu)
    {}

    /** @brief What the scene's description prints for the body. */
    std::string
    description() const override
    {
      std::ostringstream text;
      text << "plugin elastic (from a shared library): E = " << E
           << " Pa, nu = " << nu;
      return text.str();
    }

  private:
    /** Young's modulus (Pa). */
    double E;
    /** Poisson's ratio. */
    double nu;
  };

  /**
   * The registration, run when the library is loaded: the name, a line of
   * documentation, the entries of the subsection "plugin elastic" (IMPM's
   * usual elastic constants) and the function that makes the model.
   */
  const bool registered = impm::MaterialList::register_plugin(
    {"plugin elastic",
     "Hencky elasticity, from the plugin example",
     [](ParameterHandler &prm) {
       impm::ElasticConstants::declare_parameters(prm);
     },
     [](ParameterHandler  &prm,
        const std::string &path) -> std::unique_ptr<impm::Material> {
       const auto [E, nu] = impm::ElasticConstants::parse_parameters(prm, path);
       return std::make_unique<PluginElastic>(E, nu);
     }});
} // namespace plugin_example
