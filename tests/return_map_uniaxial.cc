// The stress update of HenckyVonMises (Hencky elasticity, von Mises perfect
// plasticity with the radial return in principal logarithmic strain space)
// against hand calculations, for E = 1e6, nu = 0.3, rho_y = 2e4:
//
//   lambda = E nu/((1+nu)(1-2nu)) = 3e5/0.52 = 576923.077
//   mu     = E/(2(1+nu))          = 1e6/2.6  = 384615.385
//   lambda + 2 mu = 7e5/0.52 = 1346153.85,  2 mu = 769230.769
//   K = lambda + 2 mu/3 = E/(3(1-2nu)) = 833333.333
//
// 1. Elastic uniaxial strain: dF = diag(exp(e), 1, 1), be_n = I, e = -0.01.
//    be_tr = diag(exp(2e), 1, 1), log strain eps = diag(e, 0, 0);
//    |dev eps| = |e| sqrt(2/3) = 0.00816497, rho_tr = 2 mu |dev eps| =
//    6280.74 < rho_y, so the step is elastic:
//      tau_11 = (lambda + 2 mu) e = -13461.5385
//      tau_22 = tau_33 = lambda e = -5769.23077
//    and be_new = be_tr, plastic multiplier 0.
//
// 2. Plastic uniaxial strain: the same with e = -0.05.
//    eps_tr = diag(-0.05, 0, 0), tr eps_tr = -0.05,
//    dev eps_tr = -0.05 (2/3, -1/3, -1/3), |dev eps_tr| = 0.05 sqrt(2/3)
//      = 0.0408248290, n = (-2, 1, 1)/sqrt(6)
//    s_tr = 2 mu dev eps_tr, rho_tr = |s_tr| = 31403.7147 > rho_y: plastic.
//    return ratio rho_y/rho_tr = 0.636867333
//    dgamma = (rho_tr - rho_y)/(2 mu) = 0.0408248290 - 0.026 = 0.0148248290
//    pressure tr(tau)/3 = K tr eps_tr = -41666.6667 (unchanged by the return)
//    s = rho_y n = (-16329.9316, 8164.96581, 8164.96581), |s| = rho_y
//    tau = (-57996.5983, -33501.7009, -33501.7009)
//    ln(be_new)/2 = eps_tr - dgamma n = diag(-0.0378955778, -0.00605221111,
//      -0.00605221111)
//    sqrt(det be_new) = sqrt(det be_tr) = exp(-0.05): the flow is isochoric.
//
// 3. Objectivity: dF = R, a rotation by 30 degrees about z, applied to
//    be_n = diag(exp(0.02), exp(-0.01), 1), i.e. eps_n = (0.01, -0.005, 0):
//    tau_old (the update with dF = I) = lambda 0.005 + 2 mu eps_n
//      = (10576.9231, -961.538462, 2884.61538), elastic (rho = 8308.6);
//    tau_new = R tau_old R^T, with c^2 = 3/4, s^2 = 1/4, cs = sqrt(3)/4:
//      tau_11 = 3/4 t1 + 1/4 t2 = 7692.30769
//      tau_22 = 1/4 t1 + 3/4 t2 = 1923.07692
//      tau_12 = sqrt(3)/4 (t1 - t2) = 4996.30041
//      tau_33 = t3 = 2884.61538
//    and be_new = R be_n R^T. The same check for a be_n beyond the yield
//    surface, diag(exp(-0.1), 1, 1), where the return is active in both
//    updates.

#include <impm/mechanics/material.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "tests.h"

using namespace impm;

namespace
{
  Tensor<2, 3>
  diagonal(const double a, const double b, const double c)
  {
    Tensor<2, 3> T;
    T[0][0] = a;
    T[1][1] = b;
    T[2][2] = c;
    return T;
  }

  /** The logarithm of a symmetric positive definite tensor. */
  SymmetricTensor<2, 3>
  logarithm(const SymmetricTensor<2, 3> &b)
  {
    const auto            eigen = eigenvectors(b);
    SymmetricTensor<2, 3> result;
    for (unsigned int a = 0; a < 3; ++a)
      result += std::log(eigen[a].first) *
                symmetrize(outer_product(eigen[a].second, eigen[a].second));
    return result;
  }

  double
  max_abs(const Tensor<2, 3> &T)
  {
    double result = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        result = std::max(result, std::abs(T[i][j]));
    return result;
  }

  double
  relative_error(const double value, const double expected)
  {
    return std::abs(value - expected) / std::abs(expected);
  }

  /** Print a value and whether it agrees with the hand calculation. */
  void
  compare(const std::string &what, const double value, const double expected)
  {
    std::cout << "  " << what << " = " << value << " (by hand " << expected
              << "): "
              << (relative_error(value, expected) < 1e-8 ? "yes" : "NO")
              << std::endl;
  }

  /** Check the objectivity of the update for dF = R applied to be_n. */
  void
  check_rotation(const HenckyVonMises        &material,
                 const SymmetricTensor<2, 3> &be_n,
                 const Tensor<2, 3>          &R,
                 ConstitutiveUpdate          &before,
                 ConstitutiveUpdate          &after)
  {
    material.update(unit_symmetric_tensor<3>(), be_n, before);
    material.update(R, be_n, after);
    const Tensor<2, 3> tau_old = before.kirchhoff_stress;
    const Tensor<2, 3> tau_new = after.kirchhoff_stress;
    const Tensor<2, 3> be_old  = before.elastic_left_cauchy_green;
    const Tensor<2, 3> be_new  = after.elastic_left_cauchy_green;
    std::cout << "  states: " << (before.plastic ? "plastic" : "elastic")
              << " before, " << (after.plastic ? "plastic" : "elastic")
              << " after the rotation" << std::endl;
    impm_tests::check_below("  |tau_new - R tau_old R^T|/|tau_old|",
                            max_abs(tau_new - R * tau_old * transpose(R)) /
                              max_abs(tau_old),
                            1e-12);
    impm_tests::check_below("  |be_new - R be_old R^T|",
                            max_abs(be_new - R * be_old * transpose(R)),
                            1e-12);
  }
  /** The update of @p material from the stress-free state under the
   *  uniaxial stretch exp(@p e) along x, with its title and state printed. */
  ConstitutiveUpdate
  uniaxial_update(const HenckyVonMises &material,
                  const std::string    &title,
                  const double          e)
  {
    std::cout << title << ", e = " << e << std::endl;
    ConstitutiveUpdate result;
    material.update(diagonal(std::exp(e), 1., 1.),
                    unit_symmetric_tensor<3>(),
                    result);
    std::cout << "  state: " << (result.plastic ? "plastic" : "elastic")
              << std::endl;
    return result;
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);

  const double         E = 1e6, nu = 0.3, rho_y = 2e4;
  const HenckyVonMises material(E, nu, rho_y);
  std::cout << "Hencky/von Mises, E = 1e6, nu = 0.3, rho_y = 2e4" << std::endl;
  compare("lambda", material.lame_first_parameter(), 576923.076923);
  compare("mu", material.shear_modulus(), 384615.384615);

  const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();

  // 1. Elastic uniaxial strain.
  {
    const double             e = -0.01;
    const ConstitutiveUpdate result =
      uniaxial_update(material, "Elastic uniaxial strain", e);
    const SymmetricTensor<2, 3> &tau = result.kirchhoff_stress;
    compare("tau_11", tau[0][0], -13461.5384615);
    compare("tau_22", tau[1][1], -5769.23076923);
    compare("tau_33", tau[2][2], -5769.23076923);
    impm_tests::check_below("  |off-diagonal tau|/|tau|",
                            std::max({std::abs(tau[0][1]),
                                      std::abs(tau[0][2]),
                                      std::abs(tau[1][2])}) /
                              std::abs(tau[0][0]),
                            1e-12);
    const Tensor<2, 3> be_trial = diagonal(std::exp(2. * e), 1., 1.);
    impm_tests::check_below(
      "  |be_new - be_tr|",
      max_abs(Tensor<2, 3>(result.elastic_left_cauchy_green) - be_trial),
      1e-14);
    std::cout << "  plastic multiplier = " << result.plastic_multiplier
              << std::endl;
  }

  // 2. Plastic uniaxial strain.
  {
    const double             e = -0.05;
    const ConstitutiveUpdate result =
      uniaxial_update(material, "Plastic uniaxial strain", e);
    const SymmetricTensor<2, 3> &tau = result.kirchhoff_stress;

    // The trial state, from the formulas of the comment at the top.
    SymmetricTensor<2, 3> eps_trial;
    eps_trial[0][0]                       = e;
    const SymmetricTensor<2, 3> dev_trial = deviator(eps_trial);
    const double rho_trial = 2. * material.shear_modulus() * dev_trial.norm();
    const SymmetricTensor<2, 3> n = dev_trial / dev_trial.norm();
    const double                p_trial =
      trace(material.lame_first_parameter() * trace(eps_trial) * I +
            2. * material.shear_modulus() * eps_trial) /
      3.;
    compare("rho_tr", rho_trial, 31403.7146511);
    compare("return ratio", result.return_ratio, 0.636867333124);
    compare("return ratio vs rho_y/rho_tr",
            result.return_ratio,
            rho_y / rho_trial);
    compare("plastic multiplier", result.plastic_multiplier, 0.0148248290464);
    compare("plastic multiplier vs (rho_tr - rho_y)/(2 mu)",
            result.plastic_multiplier,
            (rho_trial - rho_y) / (2. * material.shear_modulus()));
    compare("tau_11", tau[0][0], -57996.5982852);
    compare("tau_22", tau[1][1], -33501.7008574);
    compare("tau_33", tau[2][2], -33501.7008574);

    const double pressure = trace(tau) / 3.;
    compare("pressure tr(tau)/3", pressure, -41666.6666667);
    impm_tests::check_below("  |pressure - trial pressure|/|pressure|",
                            relative_error(pressure, p_trial),
                            1e-12);

    const SymmetricTensor<2, 3> s = deviator(tau);
    std::cout << "  sqrt(s:s) = " << s.norm() << std::endl;
    impm_tests::check_below("  |sqrt(s:s) - rho_y|/rho_y",
                            relative_error(s.norm(), rho_y),
                            1e-10);

    const SymmetricTensor<2, 3> eps_new =
      0.5 * logarithm(result.elastic_left_cauchy_green);
    std::cout << "  ln(be_new)/2 = diag(" << eps_new[0][0] << ", "
              << eps_new[1][1] << ", " << eps_new[2][2] << ")" << std::endl;
    impm_tests::check_below("  |ln(be_new)/2 - (eps_tr - dgamma n)|",
                            max_abs(Tensor<2, 3>(
                              eps_new -
                              (eps_trial - result.plastic_multiplier * n))),
                            1e-12);
    compare("ln(be_new)_11/2", eps_new[0][0], -0.0378955777708);
    compare("ln(be_new)_22/2", eps_new[1][1], -0.00605221111461);

    // Isochoric plastic flow: det(be)^(1/2) is the elastic volume ratio.
    const double Je_new =
      std::sqrt(determinant(result.elastic_left_cauchy_green));
    const double Je_trial = std::exp(e);
    std::cout << "  sqrt(det be_new) = " << Je_new << std::endl;
    impm_tests::check_below("  |sqrt(det be_new) - sqrt(det be_tr)|",
                            std::abs(Je_new - Je_trial),
                            1e-14);
  }

  // 3. Objectivity under a rotation by 30 degrees about z.
  {
    const double c = std::cos(numbers::PI / 6.), s = std::sin(numbers::PI / 6.);
    Tensor<2, 3> R;
    R[0][0] = c;
    R[0][1] = -s;
    R[1][0] = s;
    R[1][1] = c;
    R[2][2] = 1.;

    std::cout << "Rotation by 30 degrees about z of an elastic state"
              << std::endl;
    SymmetricTensor<2, 3> be_n;
    be_n[0][0] = std::exp(0.02);
    be_n[1][1] = std::exp(-0.01);
    be_n[2][2] = 1.;
    ConstitutiveUpdate before, after;
    check_rotation(material, be_n, R, before, after);
    compare("tau_old_11", before.kirchhoff_stress[0][0], 10576.9230769);
    compare("tau_old_22", before.kirchhoff_stress[1][1], -961.538461538);
    compare("tau_old_33", before.kirchhoff_stress[2][2], 2884.61538462);
    compare("tau_new_11", after.kirchhoff_stress[0][0], 7692.30769231);
    compare("tau_new_22", after.kirchhoff_stress[1][1], 1923.07692308);
    compare("tau_new_12", after.kirchhoff_stress[0][1], 4996.30040645);
    compare("tau_new_33", after.kirchhoff_stress[2][2], 2884.61538462);

    std::cout << "Rotation by 30 degrees about z of a state beyond yield"
              << std::endl;
    be_n       = I;
    be_n[0][0] = std::exp(-0.1);
    check_rotation(material, be_n, R, before, after);
  }
}
