#include <impm/base/errors.h>
#include <impm/mechanics/frictional_plasticity.h>

#include <cmath>
#include <sstream>

namespace impm
{
  namespace
  {
    /** Degrees to radians. */
    constexpr double degree = M_PI / 180.;

    /**
     * Relative margin of the yield check: a point returned in the step
     * before sits on the surface up to round-off, and the choice of branch
     * must not depend on it (nor on the number of processes).
     */
    constexpr double yield_margin = 1e-10;

    /** 3-vectors of the principal space. */
    using Vector3 = std::array<double, 3>;

    double
    dot(const Vector3 &a, const Vector3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
  } // namespace



  std::pair<double, double>
  CohesionLaw::branch(const double equivalent_plastic_strain) const
  {
    const double value =
      initial + hardening_modulus * equivalent_plastic_strain;
    if (hardening_modulus < 0. && value <= residual)
      return {residual, 0.};
    return {value, hardening_modulus};
  }



  void
  FrictionalParameters::declare_parameters(ParameterHandler &prm)
  {
    ElasticConstants::declare_parameters(prm);
    prm.declare_entry("Cohesion",
                      "1e4",
                      Patterns::Double(0., Patterns::Double::max_double_value),
                      "Cohesion c in Pa (>= 0).");
    prm.declare_entry("Friction angle",
                      "30",
                      Patterns::Double(0., 89.),
                      "Friction angle in degrees, in [0, 89].");
    prm.declare_entry("Dilation angle",
                      "0",
                      Patterns::Double(0., 89.),
                      "Dilation angle in degrees, in [0, friction angle]; "
                      "equal to the friction angle for associated flow.");
    prm.declare_entry("Hardening modulus",
                      "0",
                      Patterns::Double(),
                      "H = dc/d(equivalent plastic strain) in Pa: 0 for "
                      "perfect plasticity, negative for softening.");
    prm.declare_entry("Residual cohesion",
                      "0",
                      Patterns::Double(0., Patterns::Double::max_double_value),
                      "The cohesion a softening material keeps, in Pa, in "
                      "[0, Cohesion].");
  }



  void
  FrictionalParameters::parse_parameters(ParameterHandler  &prm,
                                         const std::string &path)
  {
    std::tie(youngs_modulus, poissons_ratio) =
      ElasticConstants::parse_parameters(prm, path);
    cohesion.initial           = prm.get_double("Cohesion");
    cohesion.hardening_modulus = prm.get_double("Hardening modulus");
    cohesion.residual          = prm.get_double("Residual cohesion");
    friction_angle             = prm.get_double("Friction angle") * degree;
    dilation_angle             = prm.get_double("Dilation angle") * degree;
    const auto refuse = [&](const std::string &entry, const std::string &why) {
      throw InputError("Parameter '" + path + entry + "' = '" + prm.get(entry) +
                       "' is not allowed: " + why);
    };
    if (dilation_angle > friction_angle)
      refuse("Dilation angle",
             "it must lie in [0, Friction angle = " +
               prm.get("Friction angle") + "].");
    if (cohesion.residual > cohesion.initial)
      refuse("Residual cohesion",
             "it must lie in [0, Cohesion = " + prm.get("Cohesion") + "].");
    if (cohesion.initial == 0. && friction_angle == 0.)
      refuse("Cohesion",
             "with a friction angle of 0 the material has no strength; give "
             "a cohesion > 0 or a friction angle > 0.");
  }



  std::string
  FrictionalParameters::description() const
  {
    std::ostringstream out;
    out << "E = " << youngs_modulus << ", nu = " << poissons_ratio
        << ", c = " << cohesion.initial << ", phi = " << friction_angle / degree
        << ", psi = " << dilation_angle / degree;
    if (cohesion.hardening_modulus != 0.)
      out << ", H = " << cohesion.hardening_modulus
          << ", residual c = " << cohesion.residual;
    return out.str();
  }



  std::string
  return_region_name(const ReturnRegion region)
  {
    switch (region)
      {
        case ReturnRegion::elastic:
          return "elastic";
        case ReturnRegion::smooth:
          return "smooth surface";
        case ReturnRegion::edge:
          return "edge";
        case ReturnRegion::apex:
        default:
          return "apex";
      }
  }



  PrincipalStressPlasticity::PrincipalStressPlasticity(
    const FrictionalParameters &parameters,
    const double                hardening_factor)
    : parameters(parameters)
    , lambda(parameters.youngs_modulus * parameters.poissons_ratio /
             ((1. + parameters.poissons_ratio) *
              (1. - 2. * parameters.poissons_ratio)))
    , mu(parameters.youngs_modulus / (2. * (1. + parameters.poissons_ratio)))
    , bulk(lambda + 2. * mu / 3.)
    , hardening_factor(hardening_factor)
  {}



  std::array<double, 3>
  PrincipalStressPlasticity::elastic_stress(const Vector3 &strain) const
  {
    const double trace = strain[0] + strain[1] + strain[2];
    return {{lambda * trace + 2. * mu * strain[0],
             lambda * trace + 2. * mu * strain[1],
             lambda * trace + 2. * mu * strain[2]}};
  }



  void
  PrincipalStressPlasticity::elastic_tangent(double D[3][3]) const
  {
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        D[a][b] = lambda + (a == b ? 2. * mu : 0.);
  }



  void
  PrincipalStressPlasticity::return_on_branch(const Vector3   &eigenvalues,
                                              const double     kappa,
                                              PrincipalReturn &principal) const
  {
    const Vector3 trial_strain = {{0.5 * std::log(eigenvalues[0]),
                                   0.5 * std::log(eigenvalues[1]),
                                   0.5 * std::log(eigenvalues[2])}};
    const auto   &law          = parameters.cohesion;
    const auto [c, H]          = law.branch(hardening_factor * kappa);
    principal_return(trial_strain, c, H, principal);
    // A softening cohesion that would end below its floor: the result lies
    // on the floor's branch (the yield function decreases monotonically in
    // the plastic strain, so exactly one branch is consistent).
    if (H < 0. && c + H * principal.equivalent_plastic_strain < law.residual)
      principal_return(trial_strain, law.residual, 0., principal);
  }



  void
  PrincipalStressPlasticity::update(const Tensor<2, 3>          &dF,
                                    const SymmetricTensor<2, 3> &be_n,
                                    const double                 kappa,
                                    ConstitutiveUpdate          &result) const
  {
    decompose_trial_strain(dF, be_n, result);
    result.hardening_variable = kappa;

    PrincipalReturn principal;
    return_on_branch(result.trial_eigenvalues, kappa, principal);
    result.plastic = principal.region != ReturnRegion::elastic;
    result.plastic_multiplier =
      principal.equivalent_plastic_strain / hardening_factor;

    // The elastic strain of the returned stress: tr eps = tr tau / (3K),
    // eps_a = (tau_a - lambda tr eps) / (2 mu).
    const double trace =
      (principal.stress[0] + principal.stress[1] + principal.stress[2]) /
      (3. * bulk);
    std::array<double, 3> elastic_strain;
    for (unsigned int a = 0; a < 3; ++a)
      elastic_strain[a] = (principal.stress[a] - lambda * trace) / (2. * mu);
    set_coaxial_state(principal.stress, elastic_strain, result);
  }



  void
  PrincipalStressPlasticity::response(const ConstitutiveUpdate &result,
                                      const unsigned int        n_components,
                                      const Tensor<2, 3>       &R,
                                      Tensor<4, 3>             &T) const
  {
    PrincipalReturn principal;
    return_on_branch(result.trial_eigenvalues,
                     result.hardening_variable,
                     principal);

    // Off the diagonal (tau_a - tau_b)/(eps_a - eps_b); for (nearly) equal
    // strains its limit, the symmetric difference of D.
    double shear[3][3];
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          const double strain_difference =
            0.5 *
            std::log(result.trial_eigenvalues[a] / result.trial_eigenvalues[b]);
          const auto &D = principal.tangent;
          shear[a][b] =
            std::abs(strain_difference) > 1e-10 ?
              (principal.stress[a] - principal.stress[b]) / strain_difference :
              0.5 * (D[a][a] - D[a][b] - D[b][a] + D[b][b]);
        }
    principal_frame_response(result.trial_eigenvalues,
                             result.trial_eigenvectors,
                             R,
                             principal.tangent,
                             shear,
                             n_components,
                             T);
  }



  void
  PrincipalStressPlasticity::tangent(const ConstitutiveUpdate &result,
                                     const unsigned int        n_components,
                                     Tensor<4, 3>             &C) const
  {
    response(result, n_components, transpose(result.trial_eigenvectors), C);
  }



  void
  PrincipalStressPlasticity::pulled_back_tangent(
    const ConstitutiveUpdate &result,
    const unsigned int        n_components,
    const Tensor<2, 3>       &dF_inverse,
    Tensor<4, 3>             &M) const
  {
    response(result,
             n_components,
             pull_back_rotation(result.trial_eigenvectors,
                                dF_inverse,
                                n_components),
             M);
  }



  ReturnRegion
  PrincipalStressPlasticity::return_region(
    const ConstitutiveUpdate &result) const
  {
    PrincipalReturn principal;
    return_on_branch(result.trial_eigenvalues,
                     result.hardening_variable,
                     principal);
    return principal.region;
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
    const double deviator_norm = std::sqrt(dot(deviator, deviator));
    const double pressure      = bulk * volumetric;
    const double sqrt_J2       = root2 * mu * deviator_norm;
    const double yield_value   = sqrt_J2 + eta * pressure - xi * c;
    const double scale         = sqrt_J2 + eta * std::abs(pressure) + xi * c;

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

    // The apex: p = p_tr - K deps_v = (xi/eta) c(epsp), epsp = alpha deps_v
    // with alpha = xi/eta_bar (xi/eta without dilation).
    const double alpha = xi / (eta_bar > 0. ? eta_bar : eta);
    const double beta  = xi / eta;
    const double volumetric_plastic =
      (pressure - beta * c) / (bulk + alpha * beta * H);
    const double apex_pressure = pressure - bulk * volumetric_plastic;
    const double stiffness     = bulk * (1. - bulk / (bulk + alpha * beta * H));
    for (unsigned int a = 0; a < 3; ++a)
      {
        result.stress[a] = apex_pressure;
        for (unsigned int b = 0; b < 3; ++b)
          result.tangent[a][b] = stiffness;
      }
    result.equivalent_plastic_strain = alpha * volumetric_plastic;
    result.region                    = ReturnRegion::apex;
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



  MohrCoulomb::MohrCoulomb(const FrictionalParameters &parameters)
    : PrincipalStressPlasticity(parameters,
                                2. * std::cos(parameters.friction_angle))
  {}



  bool
  MohrCoulomb::return_to_planes(
    const Vector3                              &trial_stress,
    const std::vector<std::array<unsigned, 2>> &planes,
    const double                                c,
    const double                                H,
    PrincipalReturn                            &result) const
  {
    const double sin_phi = std::sin(parameters.friction_angle);
    const double cos_phi = std::cos(parameters.friction_angle);
    const double sin_psi = std::sin(parameters.dilation_angle);
    double       De[3][3];
    elastic_tangent(De);

    // Plane k: N_k . tau - 2 c cos(phi) with N = (1 + sin phi) e_i +
    // (-1 + sin phi) e_j (i the larger stress, j the smaller); flow M_k
    // with psi. epsp = 2 cos(phi) sum dgamma.
    const unsigned int n = planes.size();
    Vector3            N[2], M[2], DeM[2], DeN[2];
    for (unsigned int k = 0; k < n; ++k)
      {
        N[k] = M[k]        = {{0., 0., 0.}};
        N[k][planes[k][0]] = 1. + sin_phi;
        N[k][planes[k][1]] = -1. + sin_phi;
        M[k][planes[k][0]] = 1. + sin_psi;
        M[k][planes[k][1]] = -1. + sin_psi;
        for (unsigned int a = 0; a < 3; ++a)
          {
            DeM[k][a] = dot({{De[a][0], De[a][1], De[a][2]}}, M[k]);
            DeN[k][a] = dot({{De[a][0], De[a][1], De[a][2]}}, N[k]);
          }
      }
    // A_kl = N_k . De M_l + 4 cos^2(phi) H, rhs_k = Phi_k(trial).
    double A[2][2], rhs[2];
    for (unsigned int k = 0; k < n; ++k)
      {
        rhs[k] = dot(N[k], trial_stress) - 2. * c * cos_phi;
        for (unsigned int l = 0; l < n; ++l)
          A[k][l] = dot(N[k], DeM[l]) + 4. * cos_phi * cos_phi * H;
      }
    double inverse[2][2];
    if (n == 1)
      inverse[0][0] = 1. / A[0][0];
    else
      {
        const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
        inverse[0][0]    = A[1][1] / det;
        inverse[1][1]    = A[0][0] / det;
        inverse[0][1]    = -A[0][1] / det;
        inverse[1][0]    = -A[1][0] / det;
      }
    double dgamma[2] = {0., 0.};
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        dgamma[k] += inverse[k][l] * rhs[l];

    result.stress = trial_stress;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int a = 0; a < 3; ++a)
        result.stress[a] -= dgamma[k] * DeM[k][a];
    // D = De - sum_kl De M_k (A^-1)_kl (De N_l)^T.
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          result.tangent[a][b] = De[a][b];
          for (unsigned int k = 0; k < n; ++k)
            for (unsigned int l = 0; l < n; ++l)
              result.tangent[a][b] -= DeM[k][a] * inverse[k][l] * DeN[l][b];
        }
    result.equivalent_plastic_strain = 2. * cos_phi * (dgamma[0] + dgamma[1]);
    result.region = (n == 1) ? ReturnRegion::smooth : ReturnRegion::edge;
    return dgamma[0] >= 0. && dgamma[1] >= 0.;
  }



  void
  MohrCoulomb::principal_return(const Vector3   &strain,
                                const double     c,
                                const double     H,
                                PrincipalReturn &result) const
  {
    const double  sin_phi = std::sin(parameters.friction_angle);
    const double  cos_phi = std::cos(parameters.friction_angle);
    const double  sin_psi = std::sin(parameters.dilation_angle);
    const Vector3 trial   = elastic_stress(strain);

    result.stress                    = trial;
    result.equivalent_plastic_strain = 0.;
    result.region                    = ReturnRegion::elastic;
    elastic_tangent(result.tangent);
    const double yield_value =
      trial[0] - trial[2] + (trial[0] + trial[2]) * sin_phi - 2. * c * cos_phi;
    const double scale =
      std::abs(trial[0]) + std::abs(trial[2]) + 2. * c * cos_phi;
    if (!(yield_value > yield_margin * scale))
      return;

    // The ordering of the stresses, up to round-off.
    const double tolerance = yield_margin * scale;
    const auto   ordered   = [&](const Vector3 &s) {
      return s[0] - s[1] >= -tolerance && s[1] - s[2] >= -tolerance;
    };

    // One plane, tau_1 - tau_3.
    if (return_to_planes(trial, {{{0, 2}}}, c, H, result) &&
        ordered(result.stress))
      return;

    // An edge: the plane (1,3) with (1,2) when tau_2 = tau_3 is reached
    // first along the return, with (2,3) when tau_1 = tau_2 is.
    const bool lower_edge =
      (1. - sin_psi) * trial[0] - 2. * trial[1] + (1. + sin_psi) * trial[2] >
      0.;
    const std::vector<std::array<unsigned, 2>> edge =
      lower_edge ? std::vector<std::array<unsigned, 2>>{{{0, 2}}, {{0, 1}}} :
                   std::vector<std::array<unsigned, 2>>{{{0, 2}}, {{1, 2}}};
    if ((return_to_planes(trial, edge, c, H, result) &&
         ordered(result.stress)) ||
        sin_phi == 0.)
      return;

    // The apex: p = p_tr - K deps_v = c(epsp) cot(phi), epsp = alpha
    // deps_v with alpha = cos(phi)/sin(psi) (sin(phi) without dilation).
    const double cot_phi  = cos_phi / sin_phi;
    const double alpha    = cos_phi / (sin_psi > 0. ? sin_psi : sin_phi);
    const double pressure = (trial[0] + trial[1] + trial[2]) / 3.;
    const double volumetric_plastic =
      (pressure - cot_phi * c) / (bulk + cot_phi * alpha * H);
    const double stiffness = bulk * (1. - bulk / (bulk + cot_phi * alpha * H));
    for (unsigned int a = 0; a < 3; ++a)
      {
        result.stress[a] = pressure - bulk * volumetric_plastic;
        for (unsigned int b = 0; b < 3; ++b)
          result.tangent[a][b] = stiffness;
      }
    result.equivalent_plastic_strain = alpha * volumetric_plastic;
    result.region                    = ReturnRegion::apex;
  }



  std::string
  MohrCoulomb::description() const
  {
    return "Mohr-Coulomb: " + parameters.description();
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

    const bool mohr_coulomb_registered = MaterialList::register_plugin(
      {"Mohr-Coulomb",
       "Hencky elasticity with Mohr-Coulomb plasticity",
       [](ParameterHandler &prm) {
         FrictionalParameters::declare_parameters(prm);
       },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         FrictionalParameters parameters;
         parameters.parse_parameters(prm, path);
         return std::make_unique<MohrCoulomb>(parameters);
       }});
  } // namespace
} // namespace impm
