#include <impm/base/errors.h>
#include <impm/mechanics/drucker_prager.h>

#include <cmath>

namespace impm
{
  namespace
  {
    /** 3-vectors of the principal space. */
    using Vector3 = std::array<double, 3>;
  } // namespace



  std::unique_ptr<Material>
  DruckerPrager::with_reduced_strength(const double factor) const
  {
    return std::make_unique<DruckerPrager>(parameters.reduced(factor), match);
  }



  DruckerPrager::DruckerPrager(const FrictionalParameters &parameters,
                               const Match                 match)
    : PrincipalStressPlasticity(parameters,
                                cone_constants(parameters.friction_angle,
                                               parameters.dilation_angle,
                                               match)[1])
    , match(match)
    , constants(cone_constants(parameters.friction_angle,
                               parameters.dilation_angle,
                               match))
  {}



  std::array<double, 3>
  DruckerPrager::cone_constants(const double friction_angle,
                                const double dilation_angle,
                                const Match  match)
  {
    const double sin_phi = std::sin(friction_angle);
    const double cos_phi = std::cos(friction_angle);
    const double sin_psi = std::sin(dilation_angle);
    switch (match)
      {
        case Match::outer_cone:
        case Match::inner_cone:
          {
            const double sign = (match == Match::outer_cone) ? -1. : 1.;
            const double root = std::sqrt(3.);
            return {{6. * sin_phi / (root * (3. + sign * sin_phi)),
                     6. * cos_phi / (root * (3. + sign * sin_phi)),
                     6. * sin_psi / (root * (3. + sign * sin_psi))}};
          }
        case Match::plane_strain:
        default:
          {
            const double eta_bar =
              std::sqrt(3.) * sin_psi / std::sqrt(3. + sin_psi * sin_psi);
            const double d =
              std::sqrt(1. - eta_bar * eta_bar / 3.) + eta_bar * sin_phi / 3.;
            return {{sin_phi / d, cos_phi / d, eta_bar}};
          }
      }
  }



  void
  DruckerPrager::principal_return(const Vector3   &strain,
                                  const double     c,
                                  const double     H,
                                  PrincipalReturn &result) const
  {
    const auto [eta, xi, eta_bar] = constants;
    const double root2            = std::sqrt(2.);

    // Trial state: p = K tr eps, s = 2 mu dev eps, sqrt(J2) = sqrt2 mu |u|.
    const double volumetric = strain[0] + strain[1] + strain[2];
    Vector3      deviator;
    for (unsigned int a = 0; a < 3; ++a)
      deviator[a] = strain[a] - volumetric / 3.;
    const double deviator_norm =
      std::sqrt(deviator[0] * deviator[0] + deviator[1] * deviator[1] +
                deviator[2] * deviator[2]);
    const double pressure    = bulk * volumetric;
    const double sqrt_J2     = root2 * mu * deviator_norm;
    const double yield_value = sqrt_J2 + eta * pressure - xi * c;
    const double scale       = sqrt_J2 + eta * std::abs(pressure) + xi * c;

    result.stress                    = elastic_stress(strain);
    result.equivalent_plastic_strain = 0.;
    result.region                    = ReturnRegion::elastic;
    elastic_tangent(result.tangent);
    if (!(yield_value > yield_margin * scale))
      return;

    // The cone: Phi(dgamma) = sqrt(J2) - mu dgamma + eta (p - K eta_bar
    // dgamma) - xi (c + H xi dgamma) = 0, linear in dgamma.
    const double A      = 1. / (mu + bulk * eta * eta_bar + xi * xi * H);
    const double dgamma = A * yield_value;
    if (eta == 0. || (deviator_norm > 0. && sqrt_J2 - mu * dgamma >= 0.))
      {
        Vector3 n;
        for (unsigned int a = 0; a < 3; ++a)
          n[a] = deviator[a] / deviator_norm;
        const double new_pressure = pressure - bulk * eta_bar * dgamma;
        const double shrink       = root2 * mu * dgamma / deviator_norm;
        for (unsigned int a = 0; a < 3; ++a)
          result.stress[a] =
            new_pressure + 2. * mu * deviator[a] - root2 * mu * dgamma * n[a];
        // D = 2 mu I_d - 2 mu^2 A n n - sqrt2 mu A eta K n 1
        //   - (sqrt2 mu dgamma / |u|) (I_d - n n) - sqrt2 mu K eta_bar A 1 n
        //   + K (1 - K eta eta_bar A) 1 1.
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            {
              const double identity_dev = (a == b ? 1. : 0.) - 1. / 3.;
              result.tangent[a][b] =
                (2. * mu - shrink) * identity_dev +
                (shrink - 2. * mu * mu * A) * n[a] * n[b] -
                root2 * mu * A * bulk * (eta * n[a] + eta_bar * n[b]) +
                bulk * (1. - bulk * eta * eta_bar * A);
            }
        result.equivalent_plastic_strain = xi * dgamma;
        result.region                    = ReturnRegion::smooth;
        return;
      }

    // The apex: p = (xi/eta) c(epsp), epsp = alpha deps_v with alpha =
    // xi/eta_bar (xi/eta without dilation).
    apex_return(
      pressure, xi / eta, xi / (eta_bar > 0. ? eta_bar : eta), c, H, result);
  }



  std::string
  DruckerPrager::description() const
  {
    return std::string("Drucker-Prager (") +
           (match == Match::plane_strain ?
              "plane-strain match" :
              (match == Match::outer_cone ? "outer cone" : "inner cone")) +
           "): " + parameters.description();
  }



  namespace
  {
    const bool drucker_prager_registered = MaterialList::register_plugin(
      {"Drucker-Prager",
       "Hencky elasticity with Drucker-Prager plasticity",
       [](ParameterHandler &prm) {
         FrictionalParameters::declare_parameters(prm);
         prm.declare_entry(
           "Match to Mohr-Coulomb",
           "plane strain",
           Patterns::Selection("plane strain|outer cone|inner cone"),
           "How the cone is fitted to the Mohr-Coulomb surface of the same "
           "cohesion and angles: 'plane strain' (the same plane-strain "
           "collapse loads), 'outer cone' (through the compressive "
           "meridians) or 'inner cone' (through the tensile meridians).");
       },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         FrictionalParameters parameters;
         parameters.parse_parameters(prm, path);
         const std::string match = prm.get("Match to Mohr-Coulomb");
         return std::make_unique<DruckerPrager>(
           parameters,
           match == "outer cone" ?
             DruckerPrager::Match::outer_cone :
             (match == "inner cone" ? DruckerPrager::Match::inner_cone :
                                      DruckerPrager::Match::plane_strain));
       }});
  } // namespace
} // namespace impm
