#ifndef impm_mechanics_spectral_decomposition_h
#define impm_mechanics_spectral_decomposition_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <utility>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The eigenvalues and unit eigenvectors of @p tensor, in
   * descending order of the eigenvalues.
   *
   * A tensor whose third axis is principal (t_xz = t_yz = 0: every tensor
   * of plane strain and axisymmetry) is decomposed in closed form, without
   * iteration. Any other by deal.II's default algorithm (QL iteration with
   * implicit shifts), and Jacobi's where that one does not converge: it fails
   * on tensors within round-off of a multiple of the identity (a trial strain
   * of 1e-8, the first step of a small load), which would otherwise fail a
   * Newton iteration that is fine.
   */
  std::array<std::pair<double, Tensor<1, 3>>, 3>
  spectral_decomposition(const SymmetricTensor<2, 3> &tensor);
} // namespace impm

#endif
