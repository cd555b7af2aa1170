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

    /** 3-vectors of the principal space. */
    using Vector3 = std::array<double, 3>;
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



  FrictionalParameters
  FrictionalParameters::reduced(const double factor) const
  {
    FrictionalParameters result = *this;
    result.cohesion.initial /= factor;
    result.cohesion.residual /= factor;
    result.cohesion.hardening_modulus /= factor;
    result.friction_angle = std::atan(std::tan(friction_angle) / factor);
    result.dilation_angle = std::atan(std::tan(dilation_angle) / factor);
    return result;
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
        case ReturnRegion::tension_cut_off:
          return "tension cut-off";
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
  PrincipalStressPlasticity::apex_return(const double     pressure,
                                         const double     apex_ratio,
                                         const double     alpha,
                                         const double     c,
                                         const double     H,
                                         PrincipalReturn &result) const
  {
    const double volumetric_plastic =
      (pressure - apex_ratio * c) / (bulk + apex_ratio * alpha * H);
    const double stiffness =
      bulk * (1. - bulk / (bulk + apex_ratio * alpha * H));
    for (unsigned int a = 0; a < 3; ++a)
      {
        result.stress[a] = pressure - bulk * volumetric_plastic;
        for (unsigned int b = 0; b < 3; ++b)
          result.tangent[a][b] = stiffness;
      }
    result.equivalent_plastic_strain = alpha * volumetric_plastic;
    result.region                    = ReturnRegion::apex;
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



  PointFields
  PrincipalStressPlasticity::state_fields() const
  {
    return {{"plastic_multiplier", 1, true}};
  }



  void
  PrincipalStressPlasticity::store_state(const ConstitutiveUpdate &result,
                                         const ArrayView<double>  &state) const
  {
    state[0] += result.plastic_multiplier;
  }



  void
  PrincipalStressPlasticity::update(const Tensor<2, 3>            &dF,
                                    const SymmetricTensor<2, 3>   &be_n,
                                    const ArrayView<const double> &state,
                                    ConstitutiveUpdate            &result) const
  {
    const double kappa = state[0];
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
} // namespace impm
