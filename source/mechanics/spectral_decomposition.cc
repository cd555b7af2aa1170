#include <deal.II/base/exceptions.h>

#include <impm/mechanics/spectral_decomposition.h>

#include <cmath>
#include <utility>

namespace impm
{
  namespace
  {
    /**
     * The spectral decomposition of a tensor whose third axis is a principal
     * axis (plane strain and axisymmetry): the in-plane block's in closed
     * form (the eigenvalues m +- R about the mean m; the first eigenvector
     * from whichever row of A - (m + R) I is free of cancellation), the
     * third eigenvalue t_zz; sorted in descending order.
     */
    std::array<std::pair<double, Tensor<1, 3>>, 3>
    block_spectral_decomposition(const SymmetricTensor<2, 3> &tensor)
    {
      const double mean   = 0.5 * (tensor[0][0] + tensor[1][1]);
      const double half   = 0.5 * (tensor[0][0] - tensor[1][1]);
      const double shear  = tensor[0][1];
      const double radius = std::sqrt(half * half + shear * shear);
      // (half + R, t_xy) and (t_xy, R - half) both span the first
      // eigenvector; the one whose leading sum adds like signs is taken.
      double x = half >= 0. ? half + radius : shear;
      double y = half >= 0. ? shear : radius - half;
      if (radius == 0.)
        {
          x = 1.;
          y = 0.;
        }
      const double length = std::sqrt(x * x + y * y);
      x /= length;
      y /= length;
      std::array<std::pair<double, Tensor<1, 3>>, 3> eigen;
      eigen[0].first     = mean + radius;
      eigen[0].second[0] = x;
      eigen[0].second[1] = y;
      eigen[1].first     = mean - radius;
      eigen[1].second[0] = -y;
      eigen[1].second[1] = x;
      eigen[2].first     = tensor[2][2];
      eigen[2].second[2] = 1.;
      // Insert the third axis at its place in the descending order.
      if (eigen[2].first > eigen[1].first)
        std::swap(eigen[1], eigen[2]);
      if (eigen[1].first > eigen[0].first)
        std::swap(eigen[0], eigen[1]);
      return eigen;
    }
  } // namespace



  std::array<std::pair<double, Tensor<1, 3>>, 3>
  spectral_decomposition(const SymmetricTensor<2, 3> &tensor)
  {
    if (tensor[0][2] == 0. && tensor[1][2] == 0.)
      return block_spectral_decomposition(tensor);
    try
      {
        return eigenvectors(tensor);
      }
    catch (const ExceptionBase &)
      {
        return eigenvectors(tensor, SymmetricTensorEigenvectorMethod::jacobi);
      }
  }
} // namespace impm
