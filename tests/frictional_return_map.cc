// The return maps of Mohr-Coulomb and Drucker-Prager against hand
// calculations, one per region of the yield surface.
//
// Material: E = 1e6, nu = 0.25 (G = lambda = 4e5, K = 666666.667),
// c = 1e4, phi = 30 deg, psi = 10 deg (non-associated). Each case starts
// from be_n = I with dF = diag(exp(e1), exp(e2), exp(e3)), so the trial
// logarithmic strains are (e1, e2, e3) and the trial stresses
// tau_a = lambda (e1 + e2 + e3) + 2 G e_a.
//
// Mohr-Coulomb, with the closed forms of de Souza Neto, Peric and Owen
// (2008), boxes 8.4 and 8.5, s_phi = sin 30, c_phi = cos 30, s_psi = sin 10,
// a = 4G(1 + s_phi s_psi/3) + 4K s_phi s_psi = 1877837.08:
//
// 1. One plane, e = (0.02, 0, -0.04): trial (8000, -8000, -40000),
//    Phi = 48000 - 32000 s_phi - 2c c_phi = 14679.4919;
//    dgamma = Phi/a = 0.00781723401;
//    tau_1 = 8000 - (2G(1 + s_psi/3) + 2K s_psi) dgamma = -425.704715
//    tau_2 = -8000 + (4G/3 - 2K) s_psi dgamma           = -9085.958752
//    tau_3 = -40000 + (2G(1 - s_psi/3) - 2K s_psi) dgamma = -35918.130295
// 2. The edge tau_2 = tau_3, e = (0.03, -0.035, -0.04): trial (6000,
//    -46000, -50000); the one-plane return gives tau_2 < tau_3, and
//    (1 - s_psi) tau_1 - 2 tau_2 + (1 + s_psi) tau_3 > 0 selects this edge;
//    b = 2G(1 + s_phi + s_psi - s_phi s_psi/3) + 4K s_phi s_psi,
//    [a b; b a] (dgamma_a, dgamma_b) = (Phi_a, Phi_b) with Phi_b the plane
//    (1,2): dgamma = (0.00760312128, 0.00155242971), tau = (-3868.192382,
//    -46245.593298, -46245.593298).
// 3. The edge tau_1 = tau_2, e = (0.01, 0.0095, -0.04): trial (-200, -600,
//    -40200), b = 2G(1 - s_phi - s_psi - s_phi s_psi/3) + 4K s_phi s_psi,
//    Phi_b the plane (2,3): dgamma = (0.00114152264, 0.000715500589),
//    tau = (-1529.771729, -1529.771729, -39230.331338).
// 4. The apex, e = (0.03, 0.03, 0.02): trial (56000, 56000, 48000); the
//    plane and the edge returns leave the ordering; tau = c cot(phi)
//    (1, 1, 1) = 17320.508076 each; deps_v = (p_tr - c cot phi)/K =
//    0.0540192379 and the multiplier deps_v/(2 s_psi) = 0.155542196.
// 5. Hardening H = 2e5 (case 1): dgamma = Phi/(a + 4 H c_phi^2) =
//    0.00592431682, tau = (1614.551629, -8822.997456, -36906.541454).
// 6. Softening H = -5e5 to a residual cohesion of 9e3 (case 1): on the
//    softening branch dgamma = 0.0388514 gives c = -23646 < 9e3, so the
//    result is on the floor: Phi with c = 9e3, dgamma = 0.00873959880,
//    tau = (-1419.863690, -9214.092324, -35436.505607).
//
// Drucker-Prager, plane-strain match: eta_bar = sqrt3 s_psi/sqrt(3 +
// s_psi^2) = 0.172782013, d = sqrt(1 - eta_bar^2/3) + eta_bar s_phi/3,
// eta = s_phi/d = 0.488372363, xi = c_phi/d = 0.845885746.
//
// 7. The cone, e = (0.02, 0, -0.04): p = K tr e = -13333.3333, sqrt(J2) =
//    24440.4037, Phi = sqrt(J2) + eta p - xi c = 9469.91474;
//    dgamma = Phi/(G + K eta eta_bar) = 0.0207557664;
//    s = (1 - G dgamma/sqrt(J2)) s_tr, p = p_tr - K eta_bar dgamma:
//    tau = (-1637.662702, -12202.527227, -33332.256278).
// 8. The apex, e = (0.03, 0.03, 0.02): p = xi c/eta = c cot(phi) =
//    17320.508076; the multiplier deps_v/eta_bar = 0.312643874.
//
// Mohr-Coulomb with a tension cut-off T = 5000 (associated Rankine planes
// tau_a <= T; lambda + 2G = 1.2e6). Flow on a tension plane is no plastic
// multiplier of the cohesion (printed 0).
//
// 9. One tension plane, e = (0.01, 0, 0): trial (12000, 4000, 4000), Mohr-
//    Coulomb 8000 + 8000 - 17320.5 < 0; dgamma = 7000/1.2e6, tau = (5000,
//    4000 - lambda dgamma, same) = (5000, 1666.666667, 1666.666667).
// 10. Two tension planes, e = (0.01, 0.008, -0.004): trial (13600, 12000,
//    2400) (Mohr-Coulomb violated too); [1.2e6 4e5; 4e5 1.2e6] dgamma =
//    (8600, 7000): dgamma = (0.005875, 0.003875), tau_3 = 2400 - lambda
//    0.00975 = -1500; Mohr-Coulomb at (5000, 5000, -1500) is 8250 - 17320.5
//    < 0.
// 11. Three tension planes, e = (0.01, 0.008, 0.006): trial (17600, 16000,
//    14400); the two-plane return leaves tau_3 = 8500 > T, so tau = (T, T,
//    T).
// 12. A Mohr-Coulomb plane with a tension plane, e = (0.02, 0, -0.02):
//    trial (16000, 0, -16000); the tension plane alone gives (5000,
//    -3666.67, -19666.67), where Mohr-Coulomb is 17333.3 - 17320.5 > 0.
//    Checked by the conditions of the return, not a closed form: both
//    surfaces hold to 1e-8, the plastic strain De^-1 (tau_tr - tau) has no
//    middle component and splits into dgamma_MC (1 + s_psi, 0, -1 + s_psi)
//    + dgamma_T (1, 0, 0) with both multipliers >= 0.
// 13. A cut-off above the apex, T = 1e5 > c cot(phi), cuts nothing: case
//    4's strain returns to the Mohr-Coulomb apex as in case 4 (17320.508076
//    each, multiplier 0.155542196).

#include <impm/mechanics/drucker_prager.h>
#include <impm/mechanics/mohr_coulomb.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  FrictionalParameters
  parameters(const double hardening = 0., const double residual = 0.)
  {
    FrictionalParameters p;
    p.youngs_modulus             = 1e6;
    p.poissons_ratio             = 0.25;
    p.cohesion.initial           = 1e4;
    p.cohesion.hardening_modulus = hardening;
    p.cohesion.residual          = residual;
    p.friction_angle             = 30. * M_PI / 180.;
    p.dilation_angle             = 10. * M_PI / 180.;
    return p;
  }


  void
  check(const std::string               &name,
        const PrincipalStressPlasticity &material,
        const std::array<double, 3>     &strain,
        const std::array<double, 3>     &expected_stress,
        const double                     expected_multiplier)
  {
    Tensor<2, 3> dF;
    for (unsigned int a = 0; a < 3; ++a)
      dF[a][a] = std::exp(strain[a]);
    ConstitutiveUpdate update;
    material.update(dF, unit_symmetric_tensor<3>(), update);

    // The multiplier relative to itself, or to 1e-3 where it is zero (flow
    // on a tension plane changes no cohesion).
    double error = std::abs(update.plastic_multiplier - expected_multiplier) /
                   (expected_multiplier > 0. ? expected_multiplier : 1e-3);
    std::cout << name << ": "
              << return_region_name(material.return_region(update)) << std::endl
              << "  stress (kPa):" << std::fixed << std::setprecision(6);
    for (unsigned int a = 0; a < 3; ++a)
      {
        std::cout << ' ' << update.kirchhoff_stress[a][a] / 1e3;
        error = std::max(error,
                         std::abs(update.kirchhoff_stress[a][a] -
                                  expected_stress[a]) /
                           std::abs(expected_stress[2]));
      }
    std::cout << std::endl
              << "  plastic multiplier x 1e3: " << std::setprecision(6)
              << update.plastic_multiplier * 1e3 << std::endl;
    std::cout << std::defaultfloat;
    impm_tests::check_below("  relative difference from the hand calculation",
                            error,
                            1e-8);
  }

} // namespace

int
main()
{
  const MohrCoulomb mohr_coulomb(parameters());
  check("Mohr-Coulomb, one plane",
        mohr_coulomb,
        {{0.02, 0., -0.04}},
        {{-425.70471463, -9085.95875248, -35918.13029528}},
        0.007817234012097793);
  check("Mohr-Coulomb, edge tau_2 = tau_3",
        mohr_coulomb,
        {{0.03, -0.035, -0.04}},
        {{-3868.19238228, -46245.59329823, -46245.59329823}},
        0.007603121276067695 + 0.001552429712414667);
  check("Mohr-Coulomb, edge tau_1 = tau_2",
        mohr_coulomb,
        {{0.01, 0.0095, -0.04}},
        {{-1529.7717289, -1529.7717289, -39230.33133807}},
        0.001141522636552691 + 0.000715500588792229);
  check("Mohr-Coulomb, apex",
        mohr_coulomb,
        {{0.03, 0.03, 0.02}},
        {{17320.508075688776, 17320.508075688776, 17320.508075688776}},
        0.15554219633124974);
  check("Mohr-Coulomb, hardening H = 2e5",
        MohrCoulomb(parameters(2e5)),
        {{0.02, 0., -0.04}},
        {{1614.55162864, -8822.99745626, -36906.5414537}},
        0.005924316823538555);
  check("Mohr-Coulomb, softening H = -5e5 to the residual 9e3",
        MohrCoulomb(parameters(-5e5, 9e3)),
        {{0.02, 0., -0.04}},
        {{-1419.86369034, -9214.0923244, -35436.50560725}},
        0.00873959880192986);

  const DruckerPrager drucker_prager(parameters(),
                                     DruckerPrager::Match::plane_strain);
  check("Drucker-Prager (plane-strain match), cone",
        drucker_prager,
        {{0.02, 0., -0.04}},
        {{-1637.66270218, -12202.52722741, -33332.25627786}},
        0.020755766437902737);
  check("Drucker-Prager (plane-strain match), apex",
        drucker_prager,
        {{0.03, 0.03, 0.02}},
        {{17320.508075688773, 17320.508075688773, 17320.508075688773}},
        0.31264387415312395);

  const MohrCoulomb cut_off(parameters(), 5000.);
  check("Mohr-Coulomb, tension cut-off, one plane",
        cut_off,
        {{0.01, 0., 0.}},
        {{5000., 1666.6666666666667, 1666.6666666666667}},
        0.);
  check("Mohr-Coulomb, tension cut-off, two planes",
        cut_off,
        {{0.01, 0.008, -0.004}},
        {{5000., 5000., -1500.}},
        0.);
  check("Mohr-Coulomb, tension cut-off, three planes",
        cut_off,
        {{0.01, 0.008, 0.006}},
        {{5000., 5000., 5000.}},
        0.);
  check("Mohr-Coulomb, tension cut-off above the apex",
        MohrCoulomb(parameters(), 1e5),
        {{0.03, 0.03, 0.02}},
        {{17320.508075688776, 17320.508075688776, 17320.508075688776}},
        0.15554219633124974);
  {
    // Case 12: the conditions of the return at a Mohr-Coulomb plane and a
    // tension plane.
    const std::array<double, 3> strain = {{0.02, 0., -0.02}};
    Tensor<2, 3>                dF;
    for (unsigned int a = 0; a < 3; ++a)
      dF[a][a] = std::exp(strain[a]);
    ConstitutiveUpdate update;
    cut_off.update(dF, unit_symmetric_tensor<3>(), update);
    const double lambda = 4e5, G = 4e5, T = 5000.;
    const double s_phi = 0.5, c_phi = std::sqrt(3.) / 2.;
    const double s_psi = std::sin(10. * M_PI / 180.);
    double       tau[3], trial[3], plastic[3];
    for (unsigned int a = 0; a < 3; ++a)
      {
        tau[a] = update.kirchhoff_stress[a][a];
        trial[a] =
          lambda * (strain[0] + strain[1] + strain[2]) + 2. * G * strain[a];
      }
    // De^-1 x = (x - lambda/(3 lambda + 2G) tr x) / 2G.
    const double trace =
      (trial[0] - tau[0]) + (trial[1] - tau[1]) + (trial[2] - tau[2]);
    for (unsigned int a = 0; a < 3; ++a)
      plastic[a] =
        ((trial[a] - tau[a]) - lambda / (3. * lambda + 2. * G) * trace) /
        (2. * G);
    const double mohr_coulomb =
      (tau[0] - tau[2] + (tau[0] + tau[2]) * s_phi - 2e4 * c_phi) / 2e4;
    const double tension   = (tau[0] - T) / T;
    const double dgamma_mc = plastic[2] / (s_psi - 1.);
    const double dgamma_t  = plastic[0] - dgamma_mc * (1. + s_psi);
    std::cout << "Mohr-Coulomb, tension cut-off, plane and tension plane: "
              << return_region_name(cut_off.return_region(update)) << std::endl
              << "  stress (kPa):" << std::fixed << std::setprecision(6) << ' '
              << tau[0] / 1e3 << ' ' << tau[1] / 1e3 << ' ' << tau[2] / 1e3
              << std::endl
              << std::defaultfloat;
    impm_tests::check_below("  on both surfaces",
                            std::max(std::abs(mohr_coulomb), std::abs(tension)),
                            1e-8);
    impm_tests::check_below("  no middle plastic strain (x 1e3)",
                            std::abs(plastic[1]) * 1e3,
                            1e-8);
    std::cout << "  both multipliers >= 0: "
              << (dgamma_mc >= 0. && dgamma_t >= 0. ? "yes" : "NO")
              << std::endl;
  }
}
