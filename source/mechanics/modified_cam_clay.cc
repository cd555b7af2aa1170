#include <deal.II/base/exceptions.h>

#include <impm/base/errors.h>
#include <impm/mechanics/modified_cam_clay.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace impm
{
  namespace
  {
    /** 3-vectors of the principal space. */
    using Vector3 = std::array<double, 3>;

    /**
     * Relative margin of the yield check: a point returned in the step
     * before sits on the surface up to round-off, and the choice of branch
     * must not depend on it (nor on the number of processes).
     */
    constexpr double yield_margin = 1e-10;
  } // namespace



  void
  ModifiedCamClay::Parameters::declare_parameters(ParameterHandler &prm)
  {
    const auto positive =
      Patterns::Double(0., Patterns::Double::max_double_value);
    prm.declare_entry("Critical state stress ratio",
                      "1",
                      positive,
                      "M = q/p' at critical state (> 0), in Kirchhoff stress; "
                      "for a critical-state friction angle phi in triaxial "
                      "compression M = 6 sin(phi)/(3 - sin(phi)).");
    prm.declare_entry("Lambda",
                      "0.2",
                      positive,
                      "lambda, the slope of the normal compression line in "
                      "e - ln p' at the initial void ratio (> Kappa). The "
                      "model uses lambda* = lambda/(1 + e0) as the slope of "
                      "ln v - ln p'.");
    prm.declare_entry("Kappa",
                      "0.04",
                      positive,
                      "kappa, the slope of the swelling line in e - ln p' at "
                      "the initial void ratio, in (0, Lambda); kappa* = "
                      "kappa/(1 + e0) sets the bulk modulus K = p'/kappa*.");
    prm.declare_entry("Initial void ratio",
                      "1",
                      positive,
                      "e0 (> 0), the void ratio at which lambda and kappa are "
                      "the slopes in e - ln p'.");
    prm.declare_entry("Shear modulus",
                      "3e6",
                      positive,
                      "The constant shear modulus G in Pa (> 0).");
    prm.declare_entry("Reference pressure",
                      "1e5",
                      positive,
                      "p_ref in Pa (> 0): the mean effective (Kirchhoff) "
                      "stress p' at zero elastic strain, so the p' of a point "
                      "that starts without a geostatic stress (no strain "
                      "gives zero stress: such a body's free boundaries are "
                      "not in equilibrium; start it geostatic).");
    prm.declare_entry("Overconsolidation ratio",
                      "1",
                      Patterns::Double(1., Patterns::Double::max_double_value),
                      "OCR >= 1: a new point's preconsolidation pressure is "
                      "OCR times the tip of the ellipse through its initial "
                      "stress, p_c = OCR (p' + q^2/(M^2 p')); 1 is normally "
                      "consolidated.");
  }



  void
  ModifiedCamClay::Parameters::parse_parameters(ParameterHandler  &prm,
                                                const std::string &path)
  {
    critical_state_ratio    = prm.get_double("Critical state stress ratio");
    lambda                  = prm.get_double("Lambda");
    kappa                   = prm.get_double("Kappa");
    initial_void_ratio      = prm.get_double("Initial void ratio");
    shear_modulus           = prm.get_double("Shear modulus");
    reference_pressure      = prm.get_double("Reference pressure");
    overconsolidation_ratio = prm.get_double("Overconsolidation ratio");
    const auto refuse = [&](const std::string &entry, const std::string &why) {
      throw InputError("Parameter '" + path + entry + "' = '" + prm.get(entry) +
                       "' is not allowed: " + why);
    };
    for (const char *entry : {"Critical state stress ratio",
                              "Lambda",
                              "Initial void ratio",
                              "Shear modulus",
                              "Reference pressure"})
      if (!(prm.get_double(entry) > 0.))
        refuse(entry, "it must be > 0.");
    if (!(kappa > 0. && kappa < lambda))
      refuse("Kappa",
             "it must lie in (0, Lambda = " + prm.get("Lambda") +
               "): the plastic compression lambda - kappa must be positive.");
  }



  std::unique_ptr<Material>
  ModifiedCamClay::with_reduced_strength(const double factor) const
  {
    const double M = parameters.critical_state_ratio;
    const double friction_angle =
      std::atan(std::tan(std::asin(3. * M / (6. + M))) / factor);
    Parameters reduced = parameters;
    reduced.critical_state_ratio =
      6. * std::sin(friction_angle) / (3. - std::sin(friction_angle));
    return std::make_unique<ModifiedCamClay>(reduced);
  }



  ModifiedCamClay::ModifiedCamClay(const Parameters &parameters)
    : parameters(parameters)
    , kappa_star(parameters.kappa / (1. + parameters.initial_void_ratio))
    , theta((parameters.lambda - parameters.kappa) /
            (1. + parameters.initial_void_ratio))
    , mu(parameters.shear_modulus)
    , M2(parameters.critical_state_ratio * parameters.critical_state_ratio)
  {}



  double
  ModifiedCamClay::mean_pressure(const SymmetricTensor<2, 3> &tau)
  {
    return -trace(tau) / 3.;
  }



  double
  ModifiedCamClay::deviatoric_stress(const SymmetricTensor<2, 3> &tau)
  {
    return std::sqrt(1.5) * deviator(tau).norm();
  }



  PointFields
  ModifiedCamClay::state_fields() const
  {
    return {{"preconsolidation_pressure", 1, true}};
  }



  void
  ModifiedCamClay::initialize_state(const SymmetricTensor<2, 3> &tau,
                                    const ArrayView<double>     &state) const
  {
    const double p = mean_pressure(tau);
    const double q = deviatoric_stress(tau);
    const double tip =
      p > 0. ? p + q * q / (M2 * p) : parameters.reference_pressure;
    state[0] = parameters.overconsolidation_ratio * tip;
  }



  double
  ModifiedCamClay::volumetric_strain_at(const double dgamma,
                                        const double eps_tr,
                                        const double pcn,
                                        double       low,
                                        double       high,
                                        const double guess) const
  {
    // g(eps) = eps - eps_tr + dgamma (2 p(eps) - p_c(eps)), increasing, with
    // g(low) <= 0 <= g(high): Newton's method, bisection where it leaves
    // the bracket.
    const double p_ref = parameters.reference_pressure;
    double       eps   = std::clamp(guess, low, high);
    for (unsigned int iteration = 0; iteration < 200; ++iteration)
      {
        const double p  = p_ref * std::exp(eps / kappa_star);
        const double pc = pcn * std::exp((eps_tr - eps) / theta);
        const double g  = eps - eps_tr + dgamma * (2. * p - pc);
        if (g == 0.)
          return eps;
        (g > 0. ? high : low) = eps;
        const double slope = 1. + dgamma * (2. * p / kappa_star + pc / theta);
        double       next  = eps - g / slope;
        if (!(next > low && next < high))
          next = 0.5 * (low + high);
        if (std::abs(next - eps) <= 1e-15 * std::max(std::abs(eps), kappa_star))
          return next;
        eps = next;
      }
    AssertThrow(false,
                ExcMessage("Modified Cam-clay: the volumetric equation of the "
                           "return did not converge."));
    return eps;
  }



  ModifiedCamClay::PrincipalReturn
  ModifiedCamClay::principal_return(const Vector3 &strain,
                                    const double   pcn) const
  {
    AssertThrow(pcn > 0. && std::isfinite(pcn),
                ExcMessage("Modified Cam-clay: the preconsolidation pressure "
                           "is not positive and finite."));
    const double p_ref = parameters.reference_pressure;
    // Trial invariants, compression positive: eps_v = -tr eps, the
    // deviator e, w = eps_s^2 = 2/3 |e|^2.
    const double eps_tr = -(strain[0] + strain[1] + strain[2]);
    Vector3      e;
    double       w = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      {
        e[a] = strain[a] + eps_tr / 3.;
        w += e[a] * e[a];
      }
    w *= 2. / 3.;
    const double p_tr = p_ref * std::exp(eps_tr / kappa_star);
    AssertThrow(p_tr > 0. && std::isfinite(p_tr),
                ExcMessage("Modified Cam-clay: the trial mean stress over- or "
                           "underflows (a volumetric strain far from any "
                           "solution)."));
    const double q_tr  = 3. * mu * std::sqrt(w);
    const double f_tr  = q_tr * q_tr / M2 + p_tr * (p_tr - pcn);
    const double scale = q_tr * q_tr / M2 + p_tr * (p_tr + pcn);

    PrincipalReturn result;
    result.preconsolidation_pressure = pcn;
    if (!(f_tr > yield_margin * scale))
      {
        for (unsigned int a = 0; a < 3; ++a)
          {
            result.stress[a]         = -p_tr + 2. * mu * e[a];
            result.elastic_strain[a] = strain[a];
            for (unsigned int b = 0; b < 3; ++b)
              result.tangent[a][b] =
                p_tr / kappa_star + 2. * mu * ((a == b ? 1. : 0.) - 1. / 3.);
          }
        result.shear_coefficient = 2. * mu;
        return result;
      }

    // The root of the volumetric equation lies between the trial strain and
    // the critical-state strain, where 2 p = p_c (closed form).
    const double eps_cs = (std::log(pcn / (2. * p_ref)) + eps_tr / theta) /
                          (1. / kappa_star + 1. / theta);
    const double low  = std::min(eps_cs, eps_tr),
                 high = std::max(eps_cs, eps_tr);
    // The yield function in dgamma: positive at 0, negative for large
    // dgamma. Newton's method, bisection once bracketed.
    const double growth = std::min(M2 / (6. * mu), kappa_star / pcn);
    double       dgamma = 0., eps = eps_tr, lower = 0.;
    double       upper = std::numeric_limits<double>::infinity();
    double       p = p_tr, pc = pcn, rho = 1.;
    bool         converged = false;
    for (unsigned int iteration = 0; iteration < 100; ++iteration)
      {
        eps = volumetric_strain_at(dgamma, eps_tr, pcn, low, high, eps);
        p   = p_ref * std::exp(eps / kappa_star);
        pc  = pcn * std::exp((eps_tr - eps) / theta);
        rho = 1. / (1. + 6. * mu * dgamma / M2);
        const double q = q_tr * rho;
        const double F = q * q / M2 + p * (p - pc);
        if (std::abs(F) <= 1e-12 * (q * q / M2 + p * (p + pc)))
          {
            converged = true;
            break;
          }
        (F > 0. ? lower : upper) = dgamma;
        if (std::isfinite(upper) && upper - lower <= 1e-15 * upper)
          {
            converged = true;
            break;
          }
        const double slope = 1. + dgamma * (2. * p / kappa_star + pc / theta);
        const double f_eps = (2. * p - pc) * p / kappa_star + p * pc / theta;
        const double dF =
          -f_eps * (2. * p - pc) / slope - 12. * mu * q * q * rho / (M2 * M2);
        double next = dF < 0. ? dgamma - F / dF : -1.;
        if (!(next > lower && next < upper))
          next =
            std::isfinite(upper) ? 0.5 * (lower + upper) : 2. * dgamma + growth;
        dgamma = next;
      }
    AssertThrow(converged,
                ExcMessage("Modified Cam-clay: the return map did not "
                           "converge."));

    result.plastic                   = true;
    result.plastic_multiplier        = dgamma;
    result.preconsolidation_pressure = pc;
    result.shear_coefficient         = 2. * mu * rho;
    for (unsigned int a = 0; a < 3; ++a)
      {
        result.stress[a]         = -p + 2. * mu * rho * e[a];
        result.elastic_strain[a] = -eps / 3. + rho * e[a];
      }
    plastic_tangent(e, q_tr, eps, dgamma, result);
    return result;
  }



  void
  ModifiedCamClay::plastic_tangent(const Vector3   &e,
                                   const double     q_tr,
                                   const double     eps,
                                   const double     dgamma,
                                   PrincipalReturn &result) const
  {
    // The residuals g1 = eps - eps_tr + dgamma (2p - p_c) and f = q^2/M^2 +
    // p (p - p_c), with q^2 = 9 G^2 w rho^2, in the unknowns (eps, dgamma)
    // and the inputs (eps_tr, w): dy/dx = -J^-1 B.
    const double p = parameters.reference_pressure * std::exp(eps / kappa_star);
    const double pc  = result.preconsolidation_pressure;
    const double rho = 1. / (1. + 6. * mu * dgamma / M2);
    const double q   = q_tr * rho;

    const double J11 = 1. + dgamma * (2. * p / kappa_star + pc / theta);
    const double J12 = 2. * p - pc;
    const double J21 = (2. * p - pc) * p / kappa_star + p * pc / theta;
    const double J22 = -12. * mu * q * q * rho / (M2 * M2);
    const double det = J11 * J22 - J12 * J21;
    AssertThrow(det != 0. && std::isfinite(det),
                ExcMessage("Modified Cam-clay: the return's Jacobian is "
                           "singular."));
    // d/d eps_tr: (c1, c2); d/dw: (0, d2).
    const double c1 = -1. - dgamma * pc / theta;
    const double c2 = -p * pc / theta;
    const double d2 = 9. * mu * mu * rho * rho / M2;

    const double deps_dtr    = -(J22 * c1 - J12 * c2) / det;
    const double dgamma_dtr  = -(-J21 * c1 + J11 * c2) / det;
    const double deps_dw     = J12 * d2 / det;
    const double dgamma_dw   = -J11 * d2 / det;
    const double drho_dgamma = -rho * rho * 6. * mu / M2;
    // d eps_tr / d eps_b = -1, dw / d eps_b = 4/3 e_b.
    for (unsigned int b = 0; b < 3; ++b)
      {
        const double deps_b   = -deps_dtr + 4. / 3. * e[b] * deps_dw;
        const double dgamma_b = -dgamma_dtr + 4. / 3. * e[b] * dgamma_dw;
        for (unsigned int a = 0; a < 3; ++a)
          result.tangent[a][b] = -p / kappa_star * deps_b +
                                 2. * mu * e[a] * drho_dgamma * dgamma_b +
                                 2. * mu * rho * ((a == b ? 1. : 0.) - 1. / 3.);
      }
  }



  void
  ModifiedCamClay::update(const Tensor<2, 3>            &dF,
                          const SymmetricTensor<2, 3>   &be_n,
                          const ArrayView<const double> &state,
                          ConstitutiveUpdate            &result) const
  {
    const double  pcn               = state[0];
    const Vector3 strain            = decompose_trial_strain(dF, be_n, result);
    result.hardening_variable       = pcn;
    const PrincipalReturn principal = principal_return(strain, pcn);
    result.plastic                  = principal.plastic;
    result.plastic_multiplier       = principal.plastic_multiplier;
    result.return_ratio             = principal.shear_coefficient / (2. * mu);
    set_coaxial_state(principal.stress, principal.elastic_strain, result);
    // The stored energy psi (the class's text), zero at p = p_ref and no
    // shear: its change is the stress's work on the elastic strain, which
    // the estimate tau : eps / 2 of set_coaxial_state() is not for a
    // pressure-dependent modulus.
    const auto  &eps_e            = principal.elastic_strain;
    const double eps_v            = -(eps_e[0] + eps_e[1] + eps_e[2]);
    double       deviator_squared = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      deviator_squared += (eps_e[a] + eps_v / 3.) * (eps_e[a] + eps_v / 3.);
    result.elastic_energy = parameters.reference_pressure * kappa_star *
                              std::expm1(eps_v / kappa_star) +
                            mu * deviator_squared;
  }



  void
  ModifiedCamClay::store_state(const ConstitutiveUpdate &result,
                               const ArrayView<double>  &state) const
  {
    if (!result.plastic)
      return;
    const auto &lambda = result.trial_eigenvalues;
    state[0]           = principal_return({{0.5 * std::log(lambda[0]),
                                            0.5 * std::log(lambda[1]),
                                            0.5 * std::log(lambda[2])}},
                                result.hardening_variable)
                 .preconsolidation_pressure;
  }



  void
  ModifiedCamClay::response(const ConstitutiveUpdate &result,
                            const unsigned int        n_components,
                            const Tensor<2, 3>       &R,
                            Tensor<4, 3>             &T) const
  {
    const auto           &lambda = result.trial_eigenvalues;
    const PrincipalReturn principal =
      principal_return({{0.5 * std::log(lambda[0]),
                         0.5 * std::log(lambda[1]),
                         0.5 * std::log(lambda[2])}},
                       result.hardening_variable);
    // Off the diagonal (tau_a - tau_b)/(eps_a - eps_b) = 2 G rho for any
    // two strains, equal or not.
    double shear[3][3];
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        shear[a][b] = principal.shear_coefficient;
    principal_frame_response(lambda,
                             result.trial_eigenvectors,
                             R,
                             principal.tangent,
                             shear,
                             n_components,
                             T);
  }



  void
  ModifiedCamClay::tangent(const ConstitutiveUpdate &result,
                           const unsigned int        n_components,
                           Tensor<4, 3>             &C) const
  {
    response(result, n_components, transpose(result.trial_eigenvectors), C);
  }



  void
  ModifiedCamClay::pulled_back_tangent(const ConstitutiveUpdate &result,
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



  SymmetricTensor<2, 3>
  ModifiedCamClay::elastic_strain_for_stress(
    const SymmetricTensor<2, 3> &tau) const
  {
    const double p = mean_pressure(tau);
    if (!(p > 0.))
      {
        std::ostringstream message;
        message << "Modified Cam-clay cannot start from a stress with p' = "
                << p
                << " Pa <= 0: its elasticity never reaches it (p' = p_ref "
                   "exp(eps_v/kappa*) > 0); start the body below its surface "
                   "level, or without an initial stress (then p' = "
                   "'Reference pressure').";
        throw InputError(message.str());
      }
    const double volumetric =
      kappa_star * std::log(p / parameters.reference_pressure);
    const auto            eigen = spectral_decomposition(tau);
    SymmetricTensor<2, 3> be;
    for (unsigned int a = 0; a < 3; ++a)
      {
        const double strain =
          -volumetric / 3. + (eigen[a].first + p) / (2. * mu);
        be += std::exp(2. * strain) *
              symmetrize(outer_product(eigen[a].second, eigen[a].second));
      }
    return be;
  }



  std::string
  ModifiedCamClay::description() const
  {
    std::ostringstream out;
    out << "Modified Cam-clay: M = " << parameters.critical_state_ratio
        << ", lambda = " << parameters.lambda
        << ", kappa = " << parameters.kappa
        << ", e0 = " << parameters.initial_void_ratio
        << ", G = " << parameters.shear_modulus
        << ", p_ref = " << parameters.reference_pressure
        << ", OCR = " << parameters.overconsolidation_ratio;
    return out.str();
  }



  double
  ModifiedCamClay::elastic_modulus() const
  {
    const double K = parameters.reference_pressure / kappa_star;
    return 9. * K * mu / (3. * K + mu);
  }



  double
  ModifiedCamClay::p_wave_modulus() const
  {
    return parameters.reference_pressure / kappa_star + 4. * mu / 3.;
  }



  double
  ModifiedCamClay::p_wave_modulus_at(
    const SymmetricTensor<2, 3> &kirchhoff_stress) const
  {
    return std::max(mean_pressure(kirchhoff_stress),
                    parameters.reference_pressure) /
             kappa_star +
           4. * mu / 3.;
  }



  namespace
  {
    const bool modified_cam_clay_registered = MaterialList::register_plugin(
      {"Modified Cam-clay",
       "Modified Cam-clay: pressure-dependent hyperelasticity, the "
       "elliptical yield surface, hardening with the plastic volume change",
       [](ParameterHandler &prm) {
         ModifiedCamClay::Parameters::declare_parameters(prm);
       },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         ModifiedCamClay::Parameters parameters;
         parameters.parse_parameters(prm, path);
         return std::make_unique<ModifiedCamClay>(parameters);
       }});
  } // namespace
} // namespace impm
