// The consistent tangent A = dP~/d(dF) of the previously converged
// formulation for Modified Cam-clay against central finite differences of
// P~(dF) (as tests/frictional_tangent.cc does for the frictional models):
// elastic, plastic on the wet side (hardening), on the dry side
// (softening), at and near the tip of the ellipse, and at very low mean
// stress, in plane strain (2D) and 3D; the model's direct route to the
// material part against the generic pull-back of C; and the major
// asymmetry A_ijkq - A_kqij, measured: zero to round-off in elastic states
// (hyperelasticity), not zero in plastic ones (the hardening follows the
// plastic volume change), so has_symmetric_tangent() is false.
//
// Material: M = 1.2, lambda = 0.2, kappa = 0.04, e0 = 1, G = 3 MPa,
// p_ref = 100 kPa. The states: b^e_n from a sheared F_n, an increment with
// shear, so the principal directions of the trial strain are neither the
// axes nor those of b^e_n; the diagonal of dF is exp(strain), p_c,n given.

#include <impm/mechanics/modified_cam_clay.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  constexpr double p0 = 1e5;

  ModifiedCamClay::Parameters
  parameters()
  {
    ModifiedCamClay::Parameters p;
    p.critical_state_ratio = 1.2;
    p.lambda               = 0.2;
    p.kappa                = 0.04;
    p.initial_void_ratio   = 1.;
    p.shear_modulus        = 3e6;
    p.reference_pressure   = p0;
    return p;
  }

  template <int dim>
  void
  check(const std::string           &name,
        const ModifiedCamClay       &material,
        const std::array<double, 3> &strain,
        const double                 preconsolidation_pressure,
        const double                 shear = 1.)
  {
    // F_n: a small shear, and in plane strain the out-of-plane stretch.
    Tensor<2, 3> Fn = unit_symmetric_tensor<3>();
    Fn[0][1]        = 0.003 * shear;
    Fn[1][0]        = -0.002 * shear;
    if (dim == 3)
      {
        Fn[0][2] = 0.002 * shear;
        Fn[2][1] = -0.0015 * shear;
      }
    else
      Fn[2][2] = std::exp(strain[2]);
    const SymmetricTensor<2, 3> be_n = symmetrize(Fn * transpose(Fn));
    const double                Jn   = determinant(Fn);

    Tensor<2, dim> dF;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        dF[i][j] = (i == j ? std::exp(strain[i]) :
                             0.002 * shear * std::sin(1. + 3. * i + 1.7 * j));

    const auto P_of = [&](const Tensor<2, dim> &F, ConstitutiveUpdate &u) {
      material.update(PulledBackStress<dim>::embed(F),
                      be_n,
                      ArrayView<const double>(&preconsolidation_pressure, 1),
                      u);
      return PulledBackStress<dim>::stress(u.kirchhoff_stress, invert(F), Jn);
    };

    ConstitutiveUpdate update;
    P_of(dF, update);
    const Tensor<2, dim> dF_inverse = invert(dF);
    Tensor<4, 3>         M_direct, M_pulled_back;
    material.pulled_back_tangent(update,
                                 dim,
                                 PulledBackStress<dim>::embed(dF_inverse),
                                 M_direct);
    material.Material::pulled_back_tangent(
      update, dim, PulledBackStress<dim>::embed(dF_inverse), M_pulled_back);
    const Tensor<4, dim> A = PulledBackStress<dim>::tangent(
      M_direct, update.kirchhoff_stress, dF_inverse, Jn);
    const Tensor<4, dim> A_pulled_back = PulledBackStress<dim>::tangent(
      M_pulled_back, update.kirchhoff_stress, dF_inverse, Jn);

    double max_error = 0., max_entry = 0., max_route_difference = 0.,
           max_asymmetry     = 0.;
    bool         same_branch = true;
    const double h           = 1e-7;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int q = 0; q < dim; ++q)
        {
          Tensor<2, dim> plus = dF, minus = dF;
          plus[k][q] += h;
          minus[k][q] -= h;
          ConstitutiveUpdate   u_plus, u_minus;
          const Tensor<2, dim> fd =
            (P_of(plus, u_plus) - P_of(minus, u_minus)) / (2. * h);
          same_branch = same_branch && u_plus.plastic == update.plastic &&
                        u_minus.plastic == update.plastic;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              {
                max_error =
                  std::max(max_error, std::abs(fd[i][j] - A[i][j][k][q]));
                max_entry = std::max(max_entry, std::abs(A[i][j][k][q]));
                max_route_difference =
                  std::max(max_route_difference,
                           std::abs(A[i][j][k][q] - A_pulled_back[i][j][k][q]));
                max_asymmetry =
                  std::max(max_asymmetry,
                           std::abs(A[i][j][k][q] - A[k][q][i][j]));
              }
        }
    const double p = ModifiedCamClay::mean_pressure(update.kirchhoff_stress);
    const double q =
      ModifiedCamClay::deviatoric_stress(update.kirchhoff_stress);
    char line[200];
    std::snprintf(line,
                  sizeof(line),
                  " p/p_c,n = %.6e, q/p = %.6f",
                  p / preconsolidation_pressure,
                  q / p);
    std::cout << name << " (" << dim
              << "D): " << (update.plastic ? "plastic" : "elastic")
              << (same_branch ? "" : " (a perturbation changes the branch)")
              << "," << line << std::endl;
    impm_tests::check_below("  relative error of the tangent",
                            max_error / max_entry,
                            1e-6);
    impm_tests::check_below("  relative difference of the direct and the "
                            "pulled-back route",
                            max_route_difference / max_entry,
                            1e-12);
    if (update.plastic)
      {
        std::snprintf(line,
                      sizeof(line),
                      "  relative major asymmetry: %.2e",
                      max_asymmetry / max_entry);
        std::cout << line << std::endl;
      }
    else
      impm_tests::check_below("  relative major asymmetry",
                              max_asymmetry / max_entry,
                              1e-10);
  }

  template <int dim>
  void
  check_states()
  {
    const ModifiedCamClay model(parameters());
    check<dim>("elastic", model, {{-0.002, 0.001, -0.001}}, 2. * p0);
    check<dim>("wet side, hardening", model, {{-0.01, -0.002, -0.004}}, p0);
    check<dim>("wet side, large step",
               model,
               {{-0.06, -0.01, -0.03}},
               1.5 * p0);
    check<dim>("dry side, softening", model, {{-0.04, 0.03, 0.01}}, 3. * p0);
    check<dim>("dry side, heavily overconsolidated",
               model,
               {{-0.08, 0.05, 0.03}},
               10. * p0);
    check<dim>("tip, isotropic (equal strains)",
               model,
               {{-0.005, -0.005, -0.005}},
               p0,
               0.);
    check<dim>("near the tip", model, {{-0.005, -0.005, -0.005}}, p0);
    check<dim>("tip, elastic unloading (equal strains)",
               model,
               {{0.001, 0.001, 0.001}},
               p0,
               0.);
    check<dim>("very low mean stress (swollen by ln J = 0.3)",
               model,
               {{0.1, 0.1, 0.1}},
               p0);
    check<dim>("low mean stress, uniaxial extension",
               model,
               {{0.2, 0., 0.}},
               p0);
  }
} // namespace

int
main()
{
  check_states<2>();
  check_states<3>();
}
