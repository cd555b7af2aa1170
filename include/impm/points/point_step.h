#ifndef impm_points_point_step_h
#define impm_points_point_step_h

#include <deal.II/base/tensor.h>

#include <impm/basis/basis_functions.h>
#include <impm/mechanics/material.h>

#include <array>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What one material point needs during one load step, in the
   * particle handler's iteration order: its support on the start-of-step
   * grid (fixed during the step) and the state of the current Newton
   * iterate.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PointStep
  {
    /** Nodes, weights and gradients (fixed during the step). */
    PointSupport<dim> support;
    /** Local indices of the support's DoFs in the nodal vectors. */
    std::array<unsigned int, PointSupport<dim>::max_nodes * dim> dofs;
    /** Deformation gradient increment of the current iterate that the
     *  material sees and the point accumulates (with F-bar: the modified
     *  one, FBar). */
    Tensor<2, dim> deformation_increment;
    /** The inverse of the true increment (from the nodal displacements),
     *  which maps the gradients to the current configuration. */
    Tensor<2, dim> deformation_increment_inverse;
    /** Initial volume @f$V_p^0@f$. */
    double initial_volume;
    /** The point's material (of its body). */
    const Material *material;
    /** Constitutive result of the current iterate. */
    ConstitutiveUpdate update;
  };
} // namespace impm

#endif
