#include <impm/mechanics/mohr_coulomb.h>

#include <cmath>

namespace impm
{
  namespace
  {
    /** 3-vectors of the principal space. */
    using Vector3 = std::array<double, 3>;

    /** The dot product of two of them. */
    double
    dot(const Vector3 &a, const Vector3 &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
  } // namespace



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

    // The apex: p = c(epsp) cot(phi), epsp = alpha deps_v with alpha =
    // cos(phi)/sin(psi) (sin(phi) without dilation).
    apex_return((trial[0] + trial[1] + trial[2]) / 3.,
                cos_phi / sin_phi,
                cos_phi / (sin_psi > 0. ? sin_psi : sin_phi),
                c,
                H,
                result);
  }



  std::string
  MohrCoulomb::description() const
  {
    return "Mohr-Coulomb: " + parameters.description();
  }



  namespace
  {
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
