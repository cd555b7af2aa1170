// The consistent tangent A = dP~/d(dF) of the previously converged
// formulation for Mohr-Coulomb and Drucker-Prager against central finite
// differences of P~(dF), in every region of the yield surface (smooth part,
// edges, apex, tension cut-off planes), with perfect plasticity, hardening and
// softening, in plane strain (2D) and 3D; the model's direct route to the
// material part against the generic pull-back of C; and major symmetry, A_ijkq
// = A_kqij, where the model claims it (associated flow).
//
// The states are those of frictional_return_map.cc, made general: the
// previous elastic strain comes from a sheared F_n and the increment has
// shear, so the principal directions of the trial strain are neither the
// axes nor those of b^e_n. In plane strain the out-of-plane trial strain
// comes from F_n.

#include <impm/mechanics/drucker_prager.h>
#include <impm/mechanics/mohr_coulomb.h>
#include <impm/mechanics/pulled_back_stress.h>

#include <array>
#include <cmath>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  FrictionalParameters
  parameters(const double dilation_angle,
             const double hardening = 0.,
             const double residual  = 0.)
  {
    FrictionalParameters p;
    p.youngs_modulus             = 1e6;
    p.poissons_ratio             = 0.25;
    p.cohesion.initial           = 1e4;
    p.cohesion.hardening_modulus = hardening;
    p.cohesion.residual          = residual;
    p.friction_angle             = 30. * M_PI / 180.;
    p.dilation_angle             = dilation_angle * M_PI / 180.;
    return p;
  }


  template <int dim>
  void
  check(const std::string               &name,
        const PrincipalStressPlasticity &material,
        const std::array<double, 3>     &strain,
        const double                     hardening_variable = 0.,
        const double                     shear              = 1.)
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
      const std::array<double, 1> state = {{hardening_variable}};
      material.update(PulledBackStress<dim>::embed(F),
                      be_n,
                      ArrayView<const double>(state.data(), state.size()),
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
    bool         same_region = true;
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
          same_region =
            same_region &&
            material.return_region(u_plus) == material.return_region(update) &&
            material.return_region(u_minus) == material.return_region(update);
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
    std::cout << name << " (" << dim
              << "D): " << return_region_name(material.return_region(update))
              << (same_region ? "" : " (a perturbation changes the region)")
              << std::endl;
    impm_tests::check_below("  relative error of the tangent",
                            max_error / max_entry,
                            1e-6);
    impm_tests::check_below("  relative difference of the direct and the "
                            "pulled-back route",
                            max_route_difference / max_entry,
                            1e-12);
    if (material.has_symmetric_tangent())
      impm_tests::check_below("  major asymmetry (claimed symmetric)",
                              max_asymmetry / max_entry,
                              1e-10);
  }

  template <int dim>
  void
  check_models()
  {
    const MohrCoulomb mc(parameters(10.));
    check<dim>("Mohr-Coulomb", mc, {{0.02, -0.04, 0.}});
    check<dim>("Mohr-Coulomb", mc, {{0.03, -0.04, -0.035}});
    check<dim>("Mohr-Coulomb", mc, {{0.012, -0.04, 0.0118}});
    // Two equal trial strains (no shear): the edge, and the off-diagonal
    // coefficient of the tangent from its limit.
    check<dim>(
      "Mohr-Coulomb, equal strains", mc, {{0.01, -0.04, 0.01}}, 0., 0.);
    check<dim>("Mohr-Coulomb", mc, {{0.03, 0.02, 0.03}});
    check<dim>("Mohr-Coulomb, elastic", mc, {{0.001, -0.002, 0.}});
    const MohrCoulomb associated(parameters(30.));
    check<dim>("Mohr-Coulomb, associated", associated, {{0.02, -0.04, 0.}});
    check<dim>("Mohr-Coulomb, associated", associated, {{0.03, -0.04, -0.039}});
    const MohrCoulomb hardening(parameters(10., 2e5));
    check<dim>("Mohr-Coulomb, hardening",
               hardening,
               {{0.03, -0.04, -0.035}},
               0.01);
    check<dim>("Mohr-Coulomb, hardening",
               hardening,
               {{0.03, -0.04, -0.039}},
               0.01);
    check<dim>("Mohr-Coulomb, hardening",
               hardening,
               {{0.03, 0.02, 0.03}},
               0.01);
    check<dim>("Mohr-Coulomb, softening",
               MohrCoulomb(parameters(10., -2e5, 5e3)),
               {{0.02, -0.04, 0.}},
               0.001);
    check<dim>("Mohr-Coulomb, softening, on the residual",
               MohrCoulomb(parameters(10., -2e5, 5e3)),
               {{0.02, -0.04, 0.}},
               0.1);
    // The tension cut-off T = 5000 (frictional_return_map.cc, cases 9-12):
    // one, two and three tension planes, a plane with a tension plane.
    const MohrCoulomb cut_off(parameters(10.), 5000.);
    check<dim>("Mohr-Coulomb, tension cut-off", cut_off, {{0.01, 0., -0.001}});
    check<dim>("Mohr-Coulomb, tension cut-off",
               cut_off,
               {{0.01, 0.008, -0.004}});
    check<dim>("Mohr-Coulomb, tension cut-off",
               cut_off,
               {{0.01, 0.008, 0.006}});
    check<dim>("Mohr-Coulomb, tension cut-off", cut_off, {{0.02, 0., -0.02}});

    for (const auto match : {DruckerPrager::Match::plane_strain,
                             DruckerPrager::Match::outer_cone,
                             DruckerPrager::Match::inner_cone})
      {
        const std::string suffix =
          match == DruckerPrager::Match::plane_strain ?
            " (plane-strain match)" :
            (match == DruckerPrager::Match::outer_cone ? " (outer cone)" :
                                                         " (inner cone)");
        const DruckerPrager dp(parameters(10.), match);
        check<dim>("Drucker-Prager" + suffix, dp, {{0.02, -0.04, 0.}});
        check<dim>("Drucker-Prager" + suffix, dp, {{0.03, 0.02, 0.03}});
        check<dim>("Drucker-Prager" + suffix + ", equal strains",
                   dp,
                   {{0.02, -0.04, 0.02}},
                   0.,
                   0.);
      }
    const DruckerPrager associated_dp(parameters(30.),
                                      DruckerPrager::Match::plane_strain);
    check<dim>("Drucker-Prager, associated",
               associated_dp,
               {{0.02, -0.04, 0.}});
    check<dim>("Drucker-Prager, hardening",
               DruckerPrager(parameters(10., 2e5),
                             DruckerPrager::Match::outer_cone),
               {{0.02, -0.04, 0.}},
               0.01);
    check<dim>("Drucker-Prager, hardening",
               DruckerPrager(parameters(10., 2e5),
                             DruckerPrager::Match::outer_cone),
               {{0.03, 0.02, 0.03}},
               0.01);
  }
} // namespace

int
main()
{
  check_models<2>();
  check_models<3>();
}
