// Material::with_reduced_strength(), the weakening a strength reduction
// applies, for every model, at F = 1.5; the values by hand (and
// python3's math):
//  * Mohr-Coulomb and Drucker-Prager (FrictionalParameters::reduced): c =
//    10 kPa -> 6666.67 Pa; phi = 30 deg -> atan(tan 30 / 1.5) = 21.0517
//    deg; psi = 10 deg -> atan(tan 10 / 1.5) = 6.7044 deg; a hardening
//    modulus of -100 kPa -> -66666.7 Pa, a residual cohesion of 2 kPa ->
//    1333.33 Pa; a tension cut-off of 3 kPa -> 2 kPa; E and nu unchanged;
//  * von Mises: the yield stress 20 kPa -> 13333.3 Pa; Hencky elastic
//    unchanged;
//  * Modified Cam-clay: M = 1.2 is phi = asin(3M/(6 + M)) = 30 deg in
//    triaxial compression; tan(phi)/1.5 gives phi = 21.0517 deg and M = 6
//    sin(phi)/(3 - sin(phi)) = 0.816144; lambda, kappa, G unchanged.
// F = 1 gives each model back unchanged.

#include <impm/mechanics/drucker_prager.h>
#include <impm/mechanics/modified_cam_clay.h>
#include <impm/mechanics/mohr_coulomb.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace impm;

int
main()
{
  std::cout << std::setprecision(6);
  FrictionalParameters frictional;
  frictional.youngs_modulus             = 1e7;
  frictional.poissons_ratio             = 0.3;
  frictional.cohesion.initial           = 1e4;
  frictional.cohesion.hardening_modulus = -1e5;
  frictional.cohesion.residual          = 2e3;
  frictional.friction_angle             = 30. * numbers::PI / 180.;
  frictional.dilation_angle             = 10. * numbers::PI / 180.;

  const FrictionalParameters reduced = frictional.reduced(1.5);
  std::cout << "reduced: c = " << reduced.cohesion.initial
            << ", H = " << reduced.cohesion.hardening_modulus
            << ", residual c = " << reduced.cohesion.residual
            << ", phi = " << reduced.friction_angle * 180. / numbers::PI
            << ", psi = " << reduced.dilation_angle * 180. / numbers::PI
            << ", E = " << reduced.youngs_modulus
            << ", nu = " << reduced.poissons_ratio << std::endl;

  const MohrCoulomb mohr_coulomb(frictional, 3e3);
  std::cout << mohr_coulomb.with_reduced_strength(1.5)->description()
            << std::endl;
  std::cout << "F = 1: "
            << (mohr_coulomb.with_reduced_strength(1.)->description() ==
                    mohr_coulomb.description() ?
                  "unchanged" :
                  "CHANGED")
            << std::endl;
  const DruckerPrager drucker_prager(frictional,
                                     DruckerPrager::Match::outer_cone);
  std::cout << drucker_prager.with_reduced_strength(1.5)->description()
            << std::endl;

  const HenckyVonMises von_mises(1e7, 0.3, 2e4);
  std::cout << von_mises.with_reduced_strength(1.5)->description() << std::endl;
  const HenckyVonMises elastic(1e7,
                               0.3,
                               std::numeric_limits<double>::infinity());
  std::cout << elastic.with_reduced_strength(1.5)->description() << std::endl;

  ModifiedCamClay::Parameters clay;
  clay.critical_state_ratio = 1.2;
  const ModifiedCamClay cam_clay(clay);
  const auto            weaker = cam_clay.with_reduced_strength(1.5);
  const auto           &reduced_clay =
    dynamic_cast<const ModifiedCamClay &>(*weaker).get_parameters();
  std::cout << "Cam-clay: M = " << reduced_clay.critical_state_ratio
            << ", lambda = " << reduced_clay.lambda
            << ", kappa = " << reduced_clay.kappa
            << ", G = " << reduced_clay.shear_modulus << std::endl;
  std::cout << "Cam-clay at F = 1: M = "
            << dynamic_cast<const ModifiedCamClay &>(
                 *cam_clay.with_reduced_strength(1.))
                 .get_parameters()
                 .critical_state_ratio
            << std::endl;
}
