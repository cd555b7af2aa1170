// The point stiffness kernel (PointStiffness) and the symmetry it may use.
//
// 1. Major symmetry, A_ijkq = A_kqij, of the tangents of the Hencky and von
//    Mises model in both statements of equilibrium (previously converged:
//    A of dP~/d(dF); updated Lagrangian: the spatial a = C - tau_il d_jk),
//    elastic and plastic, plane strain and 3D: the premise of
//    Material::has_symmetric_tangent().
// 2. The kernel against the plain six-fold sum
//    K_(v,i)(w,k) = sum_p g_vj A_ijkq g_wq over three points, for supports
//    of 4, 9 (2D), 8 and 27 (3D) nodes, with some rows not needed: all
//    entries for a tangent without symmetry, and the mirrored half for a
//    symmetric one. The kernel sums in another order, so the two agree to
//    round-off (1e-14 of the largest entry), not bit for bit.

#include <impm/mechanics/equilibrium_forms.h>
#include <impm/mechanics/point_stiffness.h>

#include <memory>
#include <random>

#include "tests.h"

using namespace impm;

template <int dim>
double
major_asymmetry(const Tensor<4, dim> &A)
{
  double largest = 0., asymmetry = 0.;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      for (unsigned int k = 0; k < dim; ++k)
        for (unsigned int q = 0; q < dim; ++q)
          {
            largest = std::max(largest, std::abs(A[i][j][k][q]));
            asymmetry =
              std::max(asymmetry, std::abs(A[i][j][k][q] - A[k][q][i][j]));
          }
  return asymmetry / largest;
}



template <int dim>
void
check_tangent_symmetry(const std::string &name,
                       const Material    &material,
                       const double       strain)
{
  Tensor<2, 3>   Fn = unit_symmetric_tensor<3>();
  Tensor<2, dim> dF = unit_symmetric_tensor<dim>();
  for (unsigned int i = 0; i < 3; ++i)
    for (unsigned int j = 0; j < 3; ++j)
      Fn[i][j] +=
        (i < dim && j < dim) ? strain * std::sin(2. + i + 2.3 * j) : 0.;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      dF[i][j] += 0.3 * strain * std::cos(1. + 1.9 * i + j);
  ConstitutiveUpdate update;
  material.update(PulledBackStress<dim>::embed(dF),
                  symmetrize(Fn * transpose(Fn)),
                  update);
  const Tensor<2, dim> dF_inverse = invert(dF);
  std::cout << name << " (" << dim << "D): state is "
            << (update.plastic ? "plastic" : "elastic") << std::endl;
  impm_tests::check_below(
    "  major asymmetry of the previously converged tangent",
    major_asymmetry(
      PreviouslyConvergedForm<dim>::tangent(material, update, dF_inverse, 1.)),
    1e-12);
  impm_tests::check_below("  major asymmetry of the updated Lagrangian tangent",
                          major_asymmetry(UpdatedLagrangianForm<dim>::tangent(
                            material, update, dF_inverse, 1.)),
                          1e-12);
}



template <int dim>
void
check_kernel(const unsigned int n_nodes, std::mt19937 &random)
{
  std::uniform_real_distribution<double>   uniform(-1., 1.);
  const unsigned int                       n        = n_nodes * dim;
  const unsigned int                       n_points = 3;
  std::vector<Tensor<4, dim>>              tangents(n_points);
  std::vector<std::vector<Tensor<1, dim>>> gradients(
    n_points, std::vector<Tensor<1, dim>>(n_nodes));
  for (unsigned int p = 0; p < n_points; ++p)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int q = 0; q < dim; ++q)
              tangents[p][i][j][k][q] = uniform(random);
      for (Tensor<1, dim> &gradient : gradients[p])
        for (unsigned int d = 0; d < dim; ++d)
          gradient[d] = uniform(random);
    }
  // Every third DoF is not in the system.
  std::vector<unsigned char> rows_needed(n);
  for (unsigned int a = 0; a < n; ++a)
    rows_needed[a] = (a % 3 != 1);

  for (const TangentSymmetry symmetry :
       {TangentSymmetry::general, TangentSymmetry::major})
    {
      std::vector<Tensor<4, dim>> used = tangents;
      if (symmetry == TangentSymmetry::major)
        for (Tensor<4, dim> &A : used)
          {
            Tensor<4, dim> symmetric;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = 0; j < dim; ++j)
                for (unsigned int k = 0; k < dim; ++k)
                  for (unsigned int q = 0; q < dim; ++q)
                    symmetric[i][j][k][q] =
                      0.5 * (A[i][j][k][q] + A[k][q][i][j]);
            A = symmetric;
          }
      const auto stiffness = std::make_unique<PointStiffness<dim>>();
      stiffness->reset(n_nodes, symmetry);
      for (unsigned int p = 0; p < n_points; ++p)
        stiffness->add(used[p], gradients[p].data(), rows_needed.data());

      double largest = 0., difference = 0.;
      for (unsigned int a = 0; a < n; ++a)
        for (unsigned int b = 0; b < n; ++b)
          {
            if (!rows_needed[a] || !rows_needed[b])
              continue;
            const unsigned int v = a / dim, i = a % dim, w = b / dim,
                               k = b % dim;
            double reference     = 0.;
            for (unsigned int p = 0; p < n_points; ++p)
              for (unsigned int j = 0; j < dim; ++j)
                for (unsigned int q = 0; q < dim; ++q)
                  reference += gradients[p][v][j] * used[p][i][j][k][q] *
                               gradients[p][w][q];
            largest    = std::max(largest, std::abs(reference));
            difference = std::max(difference,
                                  std::abs(stiffness->entry(a, b) - reference));
          }
      std::cout << dim << "D, " << n_nodes << " nodes, "
                << (symmetry == TangentSymmetry::major ? "symmetric" :
                                                         "general")
                << " tangent:" << std::endl;
      impm_tests::check_below("  kernel against the plain sum, relative",
                              difference / largest,
                              1e-14);
    }
}



int
main()
{
  const HenckyVonMises elastic(1e6,
                               0.3,
                               std::numeric_limits<double>::infinity());
  const HenckyVonMises plastic(1e6, 0.3, 2e4);
  check_tangent_symmetry<2>("Hencky elastic", elastic, 0.05);
  check_tangent_symmetry<2>("von Mises", plastic, 0.2);
  check_tangent_symmetry<3>("Hencky elastic", elastic, 0.05);
  check_tangent_symmetry<3>("von Mises", plastic, 0.2);
  std::cout << "Hencky and von Mises declare a symmetric tangent: "
            << (elastic.has_symmetric_tangent() &&
                    plastic.has_symmetric_tangent() ?
                  "yes" :
                  "no")
            << std::endl;

  std::mt19937 random(10);
  check_kernel<2>(4, random);
  check_kernel<2>(9, random);
  check_kernel<3>(8, random);
  check_kernel<3>(27, random);
}
