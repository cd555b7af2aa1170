#include <impm/base/errors.h>
#include <impm/mechanics/material.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace impm
{
  namespace
  {
    /**
     * (ln a - ln b)/(a - b), accurate also for a close to b, and 1/a for
     * a == b: the divided difference of the logarithm.
     */
    double
    log_divided_difference(const double a, const double b)
    {
      if (a == b)
        return 1. / a;
      return std::log1p((a - b) / b) / (a - b);
    }
  } // namespace



  unsigned int
  Material::n_state_entries() const
  {
    unsigned int n = 0;
    for (const PointField &field : state_fields())
      n += field.n_components;
    return n;
  }



  void
  Material::initialize_state(const SymmetricTensor<2, 3> &,
                             const ArrayView<double> &state) const
  {
    std::fill(state.begin(), state.end(), 0.);
  }



  void
  Material::update(const Tensor<2, 3>          &deformation_increment,
                   const SymmetricTensor<2, 3> &previous_elastic_strain,
                   ConstitutiveUpdate          &result) const
  {
    std::vector<double> state(n_state_entries());
    initialize_state(SymmetricTensor<2, 3>(), make_array_view(state));
    update(deformation_increment,
           previous_elastic_strain,
           make_array_view(std::as_const(state)),
           result);
  }



  void
  Material::store_state(const ConstitutiveUpdate &,
                        const ArrayView<double> &) const
  {}



  double
  Material::p_wave_modulus_at(const SymmetricTensor<2, 3> &) const
  {
    return p_wave_modulus();
  }



  double
  Material::shear_modulus() const
  {
    const double E = elastic_modulus(), M = p_wave_modulus();
    const double b = 3. * M + E;
    return (b - std::sqrt(std::max(b * b - 16. * E * M, 0.))) / 8.;
  }



  std::unique_ptr<Material>
  Material::with_reduced_strength(const double) const
  {
    throw InputError("The material '" + description() +
                     "' has no strength reduction: a factor of safety needs "
                     "one of the models that define it (von Mises, "
                     "Mohr-Coulomb, Drucker-Prager, Modified Cam-clay).");
  }



  std::unique_ptr<Material>
  HenckyVonMises::with_reduced_strength(const double factor) const
  {
    return std::make_unique<HenckyVonMises>(youngs_modulus,
                                            poissons_ratio,
                                            yield_stress / factor);
  }



  HenckyVonMises::HenckyVonMises(const double youngs_modulus,
                                 const double poissons_ratio,
                                 const double yield_stress)
    : lambda(youngs_modulus * poissons_ratio /
             ((1. + poissons_ratio) * (1. - 2. * poissons_ratio)))
    , mu(youngs_modulus / (2. * (1. + poissons_ratio)))
    , yield_stress(yield_stress)
    , youngs_modulus(youngs_modulus)
    , poissons_ratio(poissons_ratio)
  {}



  PointFields
  HenckyVonMises::state_fields() const
  {
    if (is_plastic())
      return {{"plastic_multiplier", 1, true}};
    return {};
  }



  void
  HenckyVonMises::store_state(const ConstitutiveUpdate &result,
                              const ArrayView<double>  &state) const
  {
    if (state.size() > 0)
      state[0] += result.plastic_multiplier;
  }



  void
  HenckyVonMises::update(const Tensor<2, 3>          &dF,
                         const SymmetricTensor<2, 3> &be_n,
                         const ArrayView<const double> & /*state*/,
                         ConstitutiveUpdate &result) const
  {
    std::array<double, 3> strain = decompose_trial_strain(dF, be_n, result);
    const double          trace  = strain[0] + strain[1] + strain[2];

    // Deviatoric trial strain and the yield check on rho = |s| = sqrt(2 J2).
    std::array<double, 3> deviator;
    double                deviator_norm = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      {
        deviator[a] = strain[a] - trace / 3.;
        deviator_norm += deviator[a] * deviator[a];
      }
    deviator_norm          = std::sqrt(deviator_norm);
    const double rho_trial = 2. * mu * deviator_norm;
    // A point returned to the yield surface in the last step sits on it up
    // to round-off; a relative margin keeps the choice of the elastic or the
    // plastic branch (and so the Newton path) independent of round-off, and
    // thus of the number of processes.
    result.plastic            = rho_trial > yield_stress * (1. + 1e-10);
    result.plastic_multiplier = 0.;
    result.return_ratio       = 1.;
    if (result.plastic)
      {
        result.return_ratio       = yield_stress / rho_trial;
        result.plastic_multiplier = (rho_trial - yield_stress) / (2. * mu);
        for (unsigned int a = 0; a < 3; ++a)
          {
            result.flow_direction[a] = deviator[a] / deviator_norm;
            strain[a] = trace / 3. + result.return_ratio * deviator[a];
          }
      }

    // Kirchhoff stress and elastic strain, coaxial with be_tr.
    std::array<double, 3> stress;
    for (unsigned int a = 0; a < 3; ++a)
      stress[a] = lambda * trace + 2. * mu * strain[a];
    set_coaxial_state(stress, strain, result);
  }



  void
  Material::pulled_back_tangent(const ConstitutiveUpdate &result,
                                const unsigned int        n_components,
                                const Tensor<2, 3>       &dF_inverse,
                                Tensor<4, 3>             &M) const
  {
    Tensor<4, 3> C;
    tangent(result, n_components, C);
    // M_ijkq = C_imkl dFinv_ql dFinv_jm, contracted over l, then over m.
    Tensor<4, 3> Cq;
    for (unsigned int i = 0; i < n_components; ++i)
      for (unsigned int m = 0; m < n_components; ++m)
        for (unsigned int k = 0; k < n_components; ++k)
          for (unsigned int q = 0; q < n_components; ++q)
            for (unsigned int l = 0; l < n_components; ++l)
              Cq[i][m][k][q] += C[i][m][k][l] * dF_inverse[q][l];
    M = 0;
    for (unsigned int i = 0; i < n_components; ++i)
      for (unsigned int j = 0; j < n_components; ++j)
        for (unsigned int k = 0; k < n_components; ++k)
          for (unsigned int q = 0; q < n_components; ++q)
            for (unsigned int m = 0; m < n_components; ++m)
              M[i][j][k][q] += Cq[i][m][k][q] * dF_inverse[j][m];
  }



  void
  HenckyVonMises::tangent(const ConstitutiveUpdate &r,
                          const unsigned int        n_components,
                          Tensor<4, 3>             &C) const
  {
    // Perturbations e_k (x) e_l in the global frame: R = Q^T.
    principal_response(r, n_components, transpose(r.trial_eigenvectors), C);
  }



  void
  HenckyVonMises::pulled_back_tangent(const ConstitutiveUpdate &r,
                                      const unsigned int        n_components,
                                      const Tensor<2, 3>       &dF_inverse,
                                      Tensor<4, 3>             &M) const
  {
    principal_response(r,
                       n_components,
                       pull_back_rotation(r.trial_eigenvectors,
                                          dF_inverse,
                                          n_components),
                       M);
  }



  double
  elastic_energy_density(const ConstitutiveUpdate &update)
  {
    if (!std::isnan(update.elastic_energy))
      return update.elastic_energy;
    const auto eigen = spectral_decomposition(update.elastic_left_cauchy_green);
    SymmetricTensor<2, 3> log_strain;
    for (unsigned int k = 0; k < 3; ++k)
      log_strain += 0.5 * std::log(eigen[k].first) *
                    symmetrize(outer_product(eigen[k].second, eigen[k].second));
    return 0.5 * (update.kirchhoff_stress * log_strain);
  }



  double
  plastic_dissipation_density(const ConstitutiveUpdate &update)
  {
    if (!update.plastic)
      return 0.;
    double dissipation = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      {
        Tensor<1, 3> direction;
        for (unsigned int i = 0; i < 3; ++i)
          direction[i] = update.trial_eigenvectors[i][a];
        const double stress = direction * (update.kirchhoff_stress * direction);
        const double stretch =
          direction * (update.elastic_left_cauchy_green * direction);
        dissipation +=
          stress * 0.5 *
          (std::log(update.trial_eigenvalues[a]) - std::log(stretch));
      }
    return dissipation;
  }



  std::array<double, 3>
  decompose_trial_strain(const Tensor<2, 3>          &dF,
                         const SymmetricTensor<2, 3> &be_n,
                         ConstitutiveUpdate          &result)
  {
    const Tensor<2, 3>          be_n_full = be_n;
    const SymmetricTensor<2, 3> be_trial =
      symmetrize(dF * be_n_full * transpose(dF));
    const auto            eigen = spectral_decomposition(be_trial);
    std::array<double, 3> strain;
    for (unsigned int a = 0; a < 3; ++a)
      {
        result.trial_eigenvalues[a] = eigen[a].first;
        for (unsigned int i = 0; i < 3; ++i)
          result.trial_eigenvectors[i][a] = eigen[a].second[i];
        AssertThrow(eigen[a].first > 0. && std::isfinite(eigen[a].first),
                    ExcMessage("Non-positive or non-finite stretch in the "
                               "trial elastic strain."));
        strain[a] = 0.5 * std::log(eigen[a].first);
      }
    return strain;
  }



  void
  set_coaxial_state(const std::array<double, 3> &stress,
                    const std::array<double, 3> &strain,
                    ConstitutiveUpdate          &result)
  {
    const Tensor<2, 3> &Q            = result.trial_eigenvectors;
    result.kirchhoff_stress          = 0;
    result.elastic_left_cauchy_green = 0;
    result.elastic_energy =
      0.5 *
      (stress[0] * strain[0] + stress[1] * strain[1] + stress[2] * strain[2]);
    for (unsigned int a = 0; a < 3; ++a)
      {
        const double b_a = std::exp(2. * strain[a]);
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = i; j < 3; ++j)
            {
              result.kirchhoff_stress[i][j] += stress[a] * Q[i][a] * Q[j][a];
              result.elastic_left_cauchy_green[i][j] += b_a * Q[i][a] * Q[j][a];
            }
      }
  }



  Tensor<2, 3>
  pull_back_rotation(const Tensor<2, 3> &Q,
                     const Tensor<2, 3> &dF_inverse,
                     const unsigned int  n_components)
  {
    Tensor<2, 3> R;
    for (unsigned int b = 0; b < 3; ++b)
      for (unsigned int q = 0; q < n_components; ++q)
        for (unsigned int l = 0; l < n_components; ++l)
          R[b][q] += Q[l][b] * dF_inverse[q][l];
    return R;
  }



  SymmetricTensor<2, 3>
  hencky_elastic_strain_for_stress(const double                 lambda,
                                   const double                 mu,
                                   const SymmetricTensor<2, 3> &tau)
  {
    const auto            eigen      = spectral_decomposition(tau);
    const double          volumetric = trace(tau) / (3. * lambda + 2. * mu);
    SymmetricTensor<2, 3> be;
    for (unsigned int a = 0; a < 3; ++a)
      {
        const double strain =
          (eigen[a].first - lambda * volumetric) / (2. * mu);
        be += std::exp(2. * strain) *
              symmetrize(outer_product(eigen[a].second, eigen[a].second));
      }
    return be;
  }



  void
  principal_frame_response(const std::array<double, 3> &lam,
                           const Tensor<2, 3>          &Q,
                           const Tensor<2, 3>          &R,
                           const double                 D[3][3],
                           const double                 shear[3][3],
                           const unsigned int           n_components,
                           Tensor<4, 3>                &T)
  {
    // theta_ab = d ln(lambda)/d lambda divided differences (symmetric).
    double theta[3][3];
    for (unsigned int a = 0; a < 3; ++a)
      {
        theta[a][a] = 1. / lam[a];
        for (unsigned int b = a + 1; b < 3; ++b)
          theta[a][b] = theta[b][a] = log_divided_difference(lam[a], lam[b]);
      }

    T = 0;
    for (unsigned int k = 0; k < n_components; ++k)
      for (unsigned int l = 0; l < n_components; ++l)
        {
          // G'_ab = Q_ka R_bl; d eps'_ab = 1/2 theta_ab (lambda_b G'_ab +
          // lambda_a G'_ba).
          double deps[3][3];
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              deps[a][b] =
                0.5 * theta[a][b] *
                (lam[b] * Q[k][a] * R[b][l] + lam[a] * Q[k][b] * R[a][l]);

          // d tau'_aa = D_ab d eps'_bb, d tau'_ab = c_ab d eps'_ab (a != b).
          double dtau[3][3];
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              dtau[a][b] = (a == b) ?
                             D[a][0] * deps[0][0] + D[a][1] * deps[1][1] +
                               D[a][2] * deps[2][2] :
                             shear[a][b] * deps[a][b];

          // Back to the global frame: T_imkl = Q_ia dtau'_ab R_bm.
          for (unsigned int i = 0; i < n_components; ++i)
            {
              double row[3];
              for (unsigned int b = 0; b < 3; ++b)
                row[b] = Q[i][0] * dtau[0][b] + Q[i][1] * dtau[1][b] +
                         Q[i][2] * dtau[2][b];
              for (unsigned int m = 0; m < n_components; ++m)
                T[i][m][k][l] =
                  row[0] * R[0][m] + row[1] * R[1][m] + row[2] * R[2][m];
            }
        }
  }



  void
  HenckyVonMises::principal_response(const ConstitutiveUpdate &r,
                                     const unsigned int        n_components,
                                     const Tensor<2, 3>       &R,
                                     Tensor<4, 3>             &T) const
  {
    // Elastic: lambda 1 (x) 1 + 2 mu I. Plastic: K 1 (x) 1 + 2 mu ratio
    // (I - 1/3 1 (x) 1 - n (x) n); off the diagonal 2 mu ratio.
    const double bulk     = lambda + 2. * mu / 3.;
    const double shear2   = 2. * mu * r.return_ratio;
    const double lambda_e = r.plastic ? bulk - shear2 / 3. : lambda;
    double       D[3][3], shear[3][3];
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        {
          D[a][b] = lambda_e + (a == b ? shear2 : 0.);
          if (r.plastic)
            D[a][b] -= shear2 * r.flow_direction[a] * r.flow_direction[b];
          shear[a][b] = shear2;
        }
    principal_frame_response(
      r.trial_eigenvalues, r.trial_eigenvectors, R, D, shear, n_components, T);
  }



  bool
  HenckyVonMises::is_plastic() const
  {
    return std::isfinite(yield_stress);
  }



  std::string
  HenckyVonMises::description() const
  {
    std::ostringstream out;
    out << (is_plastic() ? "von Mises" : "Hencky elastic")
        << ": E = " << youngs_modulus << ", nu = " << poissons_ratio;
    if (is_plastic())
      out << ", yield stress = " << yield_stress;
    return out.str();
  }



  double
  HenckyVonMises::elastic_modulus() const
  {
    return youngs_modulus;
  }



  namespace ElasticConstants
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Young's modulus",
                        "1e6",
                        Patterns::Double(0.,
                                         Patterns::Double::max_double_value),
                        "Young's modulus E in Pa (> 0).");
      prm.declare_entry("Poisson's ratio",
                        "0",
                        Patterns::Double(-0.999, 0.4999),
                        "Poisson's ratio, in [-0.999, 0.4999].");
    }

    std::pair<double, double>
    parse_parameters(ParameterHandler &prm, const std::string &path)
    {
      const double E  = prm.get_double("Young's modulus");
      const double nu = prm.get_double("Poisson's ratio");
      if (!(E > 0.))
        throw InputError("Parameter '" + path + "Young's modulus' = '" +
                         prm.get("Young's modulus") +
                         "' is not allowed: it must be > 0.");
      return {E, nu};
    }
  } // namespace ElasticConstants



  namespace
  {
    const bool hencky_registered = MaterialList::register_plugin(
      {"Hencky elastic",
       "Hencky elasticity",
       [](ParameterHandler &prm) { ElasticConstants::declare_parameters(prm); },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         const auto [E, nu] = ElasticConstants::parse_parameters(prm, path);
         return std::make_unique<HenckyVonMises>(
           E, nu, std::numeric_limits<double>::infinity());
       }});

    const bool von_mises_registered = MaterialList::register_plugin(
      {"von Mises",
       "Hencky elasticity with von Mises perfect plasticity",
       [](ParameterHandler &prm) {
         ElasticConstants::declare_parameters(prm);
         prm.declare_entry(
           "Yield stress",
           "2e4",
           Patterns::Double(0., Patterns::Double::max_double_value),
           "Yield strength rho_y = sqrt(2 J2) at yield, in Pa (> 0). "
           "Perfect plasticity.");
       },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         const auto [E, nu] = ElasticConstants::parse_parameters(prm, path);
         const double yield_stress = prm.get_double("Yield stress");
         if (!(yield_stress > 0.))
           throw InputError("Parameter '" + path + "Yield stress' = '" +
                            prm.get("Yield stress") +
                            "' is not allowed: it must be > 0.");
         return std::make_unique<HenckyVonMises>(E, nu, yield_stress);
       }});
  } // namespace



  namespace MaterialRegistry
  {
    void
    declare_parameters(ParameterHandler &prm)
    {
      (void)hencky_registered;
      (void)von_mises_registered;
      prm.declare_entry("Model",
                        "von Mises",
                        Patterns::Selection(MaterialList::names()),
                        "The constitutive model. Known models: " +
                          MaterialList::names() +
                          ". Its parameters are in the subsection of the "
                          "same name.");
      for (const auto &entry : MaterialList::entries())
        {
          prm.enter_subsection(entry.name);
          entry.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    std::unique_ptr<Material>
    create(ParameterHandler &prm, const std::string &path)
    {
      const auto &entry = MaterialList::find(prm.get("Model"));
      prm.enter_subsection(entry.name);
      auto material = entry.create(prm, path + "/" + entry.name + "/");
      prm.leave_subsection();
      return material;
    }
  } // namespace MaterialRegistry
} // namespace impm
