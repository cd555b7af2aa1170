// The consistent tangent A = dP~/d(dF) of the previously converged
// formulation against central finite differences of P~(dF), for Hencky
// elasticity and von Mises plasticity, in plane strain (2D) and 3D; and the
// model's direct route to its material part (perturbing dF itself) against
// the generic pull-back of C.

#include <impm/mechanics/material.h>
#include <impm/mechanics/pulled_back_stress.h>

#include "tests.h"

using namespace impm;

template <int dim>
void
check(const std::string &name,
      const Material    &material,
      const double       scale_of_increment)
{
  // A previous elastic strain be_n from a sheared, stretched F_n.
  Tensor<2, 3> Fn = unit_symmetric_tensor<3>();
  Fn[0][0]        = 1.02;
  Fn[0][1]        = 0.03;
  Fn[1][0]        = -0.01;
  Fn[1][1]        = 0.97;
  if (dim == 3)
    {
      Fn[2][2] = 1.01;
      Fn[0][2] = 0.02;
      Fn[2][1] = -0.015;
    }
  const SymmetricTensor<2, 3> be_n = symmetrize(Fn * transpose(Fn));
  const double                Jn   = determinant(Fn);

  Tensor<2, dim> dF;
  for (unsigned int i = 0; i < dim; ++i)
    for (unsigned int j = 0; j < dim; ++j)
      dF[i][j] = (i == j ? 1. : 0.) +
                 scale_of_increment * std::sin(1. + 3. * i + 1.7 * j);

  const auto P_of = [&](const Tensor<2, dim> &F, ConstitutiveUpdate &u) {
    material.update(PulledBackStress<dim>::embed(F), be_n, u);
    return PulledBackStress<dim>::stress(u.kirchhoff_stress, invert(F), Jn);
  };

  ConstitutiveUpdate update;
  P_of(dF, update);
  const Tensor<2, dim> dF_inverse = invert(dF);
  // Two routes to the material part M: the model's own (perturbing dF
  // directly) and the generic pull-back of C in the base class.
  Tensor<4, 3> M_direct, M_pulled_back;
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

  double       max_error = 0., max_entry = 0., max_route_difference = 0.;
  const double h = 1e-6;
  for (unsigned int k = 0; k < dim; ++k)
    for (unsigned int q = 0; q < dim; ++q)
      {
        Tensor<2, dim> plus = dF, minus = dF;
        plus[k][q] += h;
        minus[k][q] -= h;
        ConstitutiveUpdate   u;
        const Tensor<2, dim> fd = (P_of(plus, u) - P_of(minus, u)) / (2. * h);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            {
              max_error =
                std::max(max_error, std::abs(fd[i][j] - A[i][j][k][q]));
              max_entry = std::max(max_entry, std::abs(A[i][j][k][q]));
              max_route_difference =
                std::max(max_route_difference,
                         std::abs(A[i][j][k][q] - A_pulled_back[i][j][k][q]));
            }
      }
  std::cout << name << " (" << dim << "D): state is "
            << (update.plastic ? "plastic" : "elastic") << std::endl;
  impm_tests::check_below("  relative error of the tangent",
                          max_error / max_entry,
                          1e-6);
  impm_tests::check_below("  relative difference of the direct and the "
                          "pulled-back route",
                          max_route_difference / max_entry,
                          1e-13);
}

int
main()
{
  const HenckyVonMises elastic(1e6,
                               0.3,
                               std::numeric_limits<double>::infinity());
  const HenckyVonMises plastic(1e6, 0.3, 2e4);
  check<2>("Hencky elastic", elastic, 0.05);
  check<2>("von Mises", plastic, 0.05);
  check<3>("Hencky elastic", elastic, 0.05);
  check<3>("von Mises", plastic, 0.05);
  // A plastic state from the elastic start (be_n = I is a repeated root).
  check<2>("von Mises, tiny increment", plastic, 0.02);
}
