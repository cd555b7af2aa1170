// spectral_decomposition() of tensors whose third axis is principal (the
// closed form used in plane strain and axisymmetry) against the definition
// and against deal.II's Jacobi iteration (an independent algorithm), on
// 2,000 random tensors of three kinds and on the degenerate cases:
//
//  * positive definite, as a trial elastic left Cauchy-Green tensor
//    (stretches 0.05 to 20: log strains up to 3);
//  * indefinite, as a Kirchhoff stress (entries of either sign);
//  * with the third eigenvalue between, above and below the in-plane ones;
//  * the identity, equal in-plane eigenvalues with a different third, all
//    three equal but not the identity's scale, an off-diagonal entry of
//    1e-300, a zero tensor, and in-plane entries 1e8 apart.
//
// For each: A v_a = lambda_a v_a to round-off of |A| (|A v - lambda v| /
// |A|), the eigenvectors orthonormal, the eigenvalues in descending order
// and equal to Jacobi's to round-off of |A|; the sum of lambda_a v_a (x)
// v_a rebuilds A. A tensor with a non-zero t_xz still takes the iterative
// path (checked by the same measures).

#include <deal.II/base/symmetric_tensor.h>

#include <impm/mechanics/spectral_decomposition.h>

#include <algorithm>
#include <iostream>
#include <random>

#include "tests.h"

using namespace impm;

namespace
{
  /** The measures of one decomposition, as fractions of |A|. */
  struct Errors
  {
    double residual       = 0.;
    double orthonormality = 0.;
    double jacobi         = 0.;
    double rebuild        = 0.;
    bool   descending     = true;

    void
    merge(const Errors &other)
    {
      residual       = std::max(residual, other.residual);
      orthonormality = std::max(orthonormality, other.orthonormality);
      jacobi         = std::max(jacobi, other.jacobi);
      rebuild        = std::max(rebuild, other.rebuild);
      descending     = descending && other.descending;
    }
  };

  Errors
  measure(const SymmetricTensor<2, 3> &A)
  {
    Errors       errors;
    const auto   eigen = spectral_decomposition(A);
    const double scale = std::max(A.norm(), 1e-300);
    const auto   reference =
      eigenvectors(A, SymmetricTensorEigenvectorMethod::jacobi);
    SymmetricTensor<2, 3> rebuilt;
    for (unsigned int a = 0; a < 3; ++a)
      {
        const Tensor<1, 3> &v = eigen[a].second;
        errors.residual       = std::max(errors.residual,
                                   (A * v - eigen[a].first * v).norm() / scale);
        for (unsigned int b = 0; b < 3; ++b)
          errors.orthonormality =
            std::max(errors.orthonormality,
                     std::abs(v * eigen[b].second - (a == b ? 1. : 0.)));
        errors.jacobi =
          std::max(errors.jacobi,
                   std::abs(eigen[a].first - reference[a].first) / scale);
        if (a > 0 && eigen[a].first > eigen[a - 1].first)
          errors.descending = false;
        rebuilt += eigen[a].first * symmetrize(outer_product(v, v));
      }
    errors.rebuild = (rebuilt - A).norm() / scale;
    return errors;
  }

  SymmetricTensor<2, 3>
  block(const double xx, const double yy, const double xy, const double zz)
  {
    SymmetricTensor<2, 3> A;
    A[0][0] = xx;
    A[1][1] = yy;
    A[0][1] = xy;
    A[2][2] = zz;
    return A;
  }

  void
  report(const std::string &what, const Errors &errors)
  {
    std::cout << what << std::endl;
    impm_tests::check_below("  |A v - lambda v| / |A|", errors.residual, 1e-14);
    impm_tests::check_below("  |v_a . v_b - delta_ab|",
                            errors.orthonormality,
                            1e-14);
    impm_tests::check_below("  |lambda - Jacobi's| / |A|",
                            errors.jacobi,
                            1e-14);
    impm_tests::check_below("  |sum lambda v (x) v - A| / |A|",
                            errors.rebuild,
                            1e-14);
    std::cout << "  descending order: " << (errors.descending ? "yes" : "NO")
              << std::endl;
  }
} // namespace

int
main()
{
  std::mt19937                           generator(20261127);
  std::uniform_real_distribution<double> unit(-1., 1.);

  Errors stretch, stress;
  for (unsigned int n = 0; n < 1000; ++n)
    {
      // b = Q diag(s1^2, s2^2) Q^T in the plane, s3^2 on z: log stretches up
      // to 3 in size.
      const double angle = 3.2 * unit(generator);
      const double b1    = std::exp(2. * 1.5 * unit(generator)),
                   b2    = std::exp(2. * 1.5 * unit(generator)),
                   b3    = std::exp(2. * 1.5 * unit(generator));
      const double c = std::cos(angle), s = std::sin(angle);
      stretch.merge(measure(block(c * c * b1 + s * s * b2,
                                  s * s * b1 + c * c * b2,
                                  c * s * (b1 - b2),
                                  b3)));
      stress.merge(measure(block(1e5 * unit(generator),
                                 1e5 * unit(generator),
                                 1e5 * unit(generator),
                                 1e5 * unit(generator))));
    }
  report("1000 positive definite block tensors (stretches 0.05 to 20)",
         stretch);
  report("1000 indefinite block tensors (stresses of either sign)", stress);

  Errors degenerate;
  for (const auto &A : {block(1., 1., 0., 1.),
                        block(2., 2., 0., 1.),
                        block(2., 2., 0., 3.),
                        block(1., 3., 0., 2.),
                        block(-4e3, -4e3, 0., -4e3),
                        block(1., 1., 1e-300, 1.),
                        block(0., 0., 0., 0.),
                        block(1e8, 1., 0., 1.),
                        block(1., 1e8, 1e-3, 1.)})
    degenerate.merge(measure(A));
  report("9 degenerate block tensors (equal eigenvalues, zero, 1e8 apart)",
         degenerate);

  Errors general;
  for (unsigned int n = 0; n < 100; ++n)
    {
      SymmetricTensor<2, 3> A = block(unit(generator),
                                      unit(generator),
                                      unit(generator),
                                      unit(generator));
      A[0][2]                 = unit(generator);
      A[1][2]                 = 0.5 * unit(generator);
      general.merge(measure(A));
    }
  report("100 general tensors (the iterative path)", general);
}
