#include <deal.II/base/utilities.h>

#include <impm/mechanics/mohr_coulomb.h>

#include <algorithm>
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



  std::unique_ptr<Material>
  MohrCoulomb::with_reduced_strength(const double factor) const
  {
    return std::make_unique<MohrCoulomb>(parameters.reduced(factor),
                                         tensile_strength < 0. ?
                                           tensile_strength :
                                           tensile_strength / factor);
  }



  MohrCoulomb::MohrCoulomb(const FrictionalParameters &parameters,
                           const double                tensile_strength)
    : PrincipalStressPlasticity(parameters,
                                2. * std::cos(parameters.friction_angle))
    , tensile_strength(tensile_strength)
  {}



  void
  MohrCoulomb::declare_parameters(ParameterHandler &prm)
  {
    FrictionalParameters::declare_parameters(prm);
    prm.declare_entry("Tension cut-off",
                      "false",
                      Patterns::Bool(),
                      "Bound every principal stress by the tensile strength "
                      "(a Rankine cut-off with associated flow).");
    prm.declare_entry("Tensile strength",
                      "0",
                      Patterns::Double(0., Patterns::Double::max_double_value),
                      "The tension cut-off T in Pa (>= 0); where it is not "
                      "below the apex pressure c cot(phi) (a softened "
                      "cohesion can lower it) it cuts nothing.");
  }



  MohrCoulomb::Surface
  MohrCoulomb::plane(const unsigned int larger,
                     const unsigned int smaller,
                     const double       c) const
  {
    // N . tau - 2 c cos(phi) with N = (1 + sin phi) e_i + (-1 + sin phi)
    // e_j (i the larger stress, j the smaller); flow M with psi.
    const double sin_phi = std::sin(parameters.friction_angle);
    const double cos_phi = std::cos(parameters.friction_angle);
    const double sin_psi = std::sin(parameters.dilation_angle);
    Surface      surface;
    surface.normal = surface.flow = {{0., 0., 0.}};
    surface.normal[larger]        = 1. + sin_phi;
    surface.normal[smaller]       = -1. + sin_phi;
    surface.flow[larger]          = 1. + sin_psi;
    surface.flow[smaller]         = -1. + sin_psi;
    surface.level                 = 2. * c * cos_phi;
    surface.cohesive              = true;
    return surface;
  }



  bool
  MohrCoulomb::return_to_surfaces(const Vector3              &trial_stress,
                                  const std::vector<Surface> &surfaces,
                                  const double                H,
                                  PrincipalReturn            &result) const
  {
    const double cos_phi = std::cos(parameters.friction_angle);
    double       De[3][3];
    elastic_tangent(De);

    const unsigned int n = surfaces.size();
    Vector3            DeM[3], DeN[3];
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int a = 0; a < 3; ++a)
        {
          DeM[k][a] = dot({{De[a][0], De[a][1], De[a][2]}}, surfaces[k].flow);
          DeN[k][a] = dot({{De[a][0], De[a][1], De[a][2]}}, surfaces[k].normal);
        }
    // A_kl = N_k . De M_l (+ 4 cos^2(phi) H between cohesive surfaces),
    // rhs_k = Phi_k(trial).
    double A[3][3], rhs[3];
    for (unsigned int k = 0; k < n; ++k)
      {
        rhs[k] = dot(surfaces[k].normal, trial_stress) - surfaces[k].level;
        for (unsigned int l = 0; l < n; ++l)
          A[k][l] = dot(surfaces[k].normal, DeM[l]) +
                    (surfaces[k].cohesive && surfaces[l].cohesive ?
                       4. * cos_phi * cos_phi * H :
                       0.);
      }
    double inverse[3][3];
    if (n == 1)
      inverse[0][0] = 1. / A[0][0];
    else if (n == 2)
      {
        const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
        inverse[0][0]    = A[1][1] / det;
        inverse[1][1]    = A[0][0] / det;
        inverse[0][1]    = -A[0][1] / det;
        inverse[1][0]    = -A[1][0] / det;
      }
    else
      {
        Tensor<2, 3> matrix;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            matrix[k][l] = A[k][l];
        const Tensor<2, 3> inverted = invert(matrix);
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            inverse[k][l] = inverted[k][l];
      }
    double dgamma[3] = {0., 0., 0.};
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
    // Only the cohesive surfaces' multipliers are plastic strain.
    double cohesive_multiplier = 0.;
    bool   on_tension_plane    = false;
    for (unsigned int k = 0; k < n; ++k)
      if (surfaces[k].cohesive)
        cohesive_multiplier += dgamma[k];
      else
        on_tension_plane = true;
    result.equivalent_plastic_strain = 2. * cos_phi * cohesive_multiplier;
    result.region   = on_tension_plane ? ReturnRegion::tension_cut_off :
                      (n == 1)         ? ReturnRegion::smooth :
                                         ReturnRegion::edge;
    bool admissible = true;
    for (unsigned int k = 0; k < n; ++k)
      admissible = admissible && dgamma[k] >= 0.;
    return admissible;
  }



  void
  MohrCoulomb::return_with_cut_off(const Vector3   &trial,
                                   const double     c,
                                   const double     H,
                                   PrincipalReturn &result) const
  {
    const double cos_phi = std::cos(parameters.friction_angle);
    const double cutoff  = tensile_strength;
    // The candidates, the likely ones first.
    std::array<Surface, 6> all = {
      {plane(0, 2, c), {}, plane(0, 1, c), plane(1, 2, c), {}, {}}};
    const unsigned int tension_index[3] = {1, 4, 5};
    for (unsigned int a = 0; a < 3; ++a)
      {
        Surface &tension = all[tension_index[a]];
        tension.normal = tension.flow = {{0., 0., 0.}};
        tension.normal[a] = tension.flow[a] = 1.;
        tension.level                       = cutoff;
        tension.cohesive                    = false;
      }
    const double tolerance =
      yield_margin *
      (std::abs(trial[0]) + std::abs(trial[2]) + 2. * c * cos_phi + cutoff);
    const auto admissible = [&](const PrincipalReturn &candidate) {
      if (candidate.stress[0] - candidate.stress[1] < -tolerance ||
          candidate.stress[1] - candidate.stress[2] < -tolerance)
        return false;
      // The cohesion at the end of the return.
      const double shift =
        2. * cos_phi * H * candidate.equivalent_plastic_strain;
      for (const Surface &surface : all)
        if (dot(surface.normal, candidate.stress) - surface.level -
              (surface.cohesive ? shift : 0.) >
            tolerance)
          return false;
      return true;
    };
    std::vector<Surface> active;
    for (unsigned int size = 1; size <= 3; ++size)
      for (unsigned int mask = 1; mask < (1u << all.size()); ++mask)
        {
          if (static_cast<unsigned int>(__builtin_popcount(mask)) != size)
            continue;
          active.clear();
          for (unsigned int k = 0; k < all.size(); ++k)
            if (mask & (1u << k))
              active.push_back(all[k]);
          if (return_to_surfaces(trial, active, H, result) &&
              admissible(result))
            return;
        }
    AssertThrow(false,
                ExcMessage("The Mohr-Coulomb return with tension cut-off "
                           "found no admissible set of active surfaces."));
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
    // A cut-off at or above the apex pressure c cot(phi) cuts nothing.
    if (tensile_strength >= 0. &&
        (sin_phi == 0. || tensile_strength < c * cos_phi / sin_phi))
      {
        if (yield_value > yield_margin * scale ||
            trial[0] - tensile_strength >
              yield_margin * (scale + tensile_strength))
          return_with_cut_off(trial, c, H, result);
        return;
      }
    if (!(yield_value > yield_margin * scale))
      return;

    // The ordering of the stresses, up to round-off.
    const double tolerance = yield_margin * scale;
    const auto   ordered   = [&](const Vector3 &s) {
      return s[0] - s[1] >= -tolerance && s[1] - s[2] >= -tolerance;
    };

    // One plane, tau_1 - tau_3.
    if (return_to_surfaces(trial, {plane(0, 2, c)}, H, result) &&
        ordered(result.stress))
      return;

    // An edge: the plane (1,3) with (1,2) when tau_2 = tau_3 is reached
    // first along the return, with (2,3) when tau_1 = tau_2 is.
    const bool lower_edge =
      (1. - sin_psi) * trial[0] - 2. * trial[1] + (1. + sin_psi) * trial[2] >
      0.;
    const std::vector<Surface> edge = {plane(0, 2, c),
                                       lower_edge ? plane(0, 1, c) :
                                                    plane(1, 2, c)};
    if ((return_to_surfaces(trial, edge, H, result) &&
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
    std::string text = "Mohr-Coulomb: " + parameters.description();
    if (tensile_strength >= 0.)
      text += ", tension cut-off T = " + Utilities::to_string(tensile_strength);
    return text;
  }



  namespace
  {
    const bool mohr_coulomb_registered = MaterialList::register_plugin(
      {"Mohr-Coulomb",
       "Hencky elasticity with Mohr-Coulomb plasticity",
       [](ParameterHandler &prm) { MohrCoulomb::declare_parameters(prm); },
       [](ParameterHandler  &prm,
          const std::string &path) -> std::unique_ptr<Material> {
         FrictionalParameters parameters;
         parameters.parse_parameters(prm, path);
         return std::make_unique<MohrCoulomb>(parameters,
                                              prm.get_bool("Tension cut-off") ?
                                                prm.get_double(
                                                  "Tensile strength") :
                                                -1.);
       }});
  } // namespace
} // namespace impm
