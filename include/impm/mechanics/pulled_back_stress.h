#ifndef impm_mechanics_pulled_back_stress_h
#define impm_mechanics_pulled_back_stress_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <impm/mechanics/material.h>

namespace impm
{
  using namespace dealii;

  /**
   * @brief Axisymmetry: the entries of the tangent times the volume,
   * @f$A V^n@f$, that pair an in-plane index pair with the hoop pair
   * @f$\theta\theta@f$ (the rest of the tangent couples no hoop entry: in
   * axisymmetry @f$\Delta F@f$ and @f$\tau@f$ have no in-plane-hoop
   * entries).
   *
   * @tparam dim Space dimension (2: the meridian plane).
   */
  template <int dim>
  struct HoopTangent
  {
    /** @f$A_{ij\theta\theta} V^n@f$: the in-plane stress's change with
     *  the hoop stretch. */
    Tensor<2, dim> in_plane_by_hoop;
    /** @f$A_{\theta\theta kq} V^n@f$: the hoop stress's change with the
     *  in-plane increment. */
    Tensor<2, dim> hoop_by_in_plane;
    /** @f$A_{\theta\theta\theta\theta} V^n@f$. */
    double hoop_by_hoop = 0.;
  };

  /**
   * @brief The stress of the previously converged formulation and its
   * consistent tangent (the paper's eq. 10; formulation note, section 3).
   *
   * @f$\tilde P_{ij} = \tau_{im}\,\Delta F^{-1}_{jm} / J_n@f$ and
   * @f$A_{ijkq} = \partial \tilde P_{ij}/\partial \Delta F_{kq}
   *   = \frac{1}{J_n}[\mathcal C_{imkl}\Delta F^{-1}_{ql}\Delta F^{-1}_{jm}
   *   - \tau_{im}\Delta F^{-1}_{qm}\Delta F^{-1}_{jk}]@f$, all for indices
   * below @p dim (in plane strain the out-of-plane terms do not couple).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PulledBackStress
  {
    /**
     * @brief Embed a dim x dim deformation increment as 3x3 (plane strain:
     * unit out-of-plane stretch).
     */
    static Tensor<2, 3>
    embed(const Tensor<2, dim> &F)
    {
      Tensor<2, 3> full = unit_symmetric_tensor<3>();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          full[i][j] = F[i][j];
      return full;
    }

    /**
     * @brief @f$\tilde P = \tau \Delta F^{-T}/J_n@f$.
     *
     * @param tau Kirchhoff stress.
     * @param dF_inverse @f$\Delta F^{-1}@f$.
     * @param previous_jacobian @f$J_n = \det F_n@f$.
     */
    static Tensor<2, dim>
    stress(const SymmetricTensor<2, 3> &tau,
           const Tensor<2, dim>        &dF_inverse,
           const double                 previous_jacobian)
    {
      Tensor<2, dim> P;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            double value = 0.;
            for (unsigned int m = 0; m < dim; ++m)
              value += tau[i][m] * dF_inverse[j][m];
            P[i][j] = value / previous_jacobian;
          }
      return P;
    }

    /**
     * @brief The consistent tangent @f$A_{ijkq}@f$ from the material part
     * already pulled back (Material::pulled_back_tangent()):
     * @f$A_{ijkq} = (M_{ijkq} - \tau_{im}\Delta F^{-1}_{qm}
     * \Delta F^{-1}_{jk})/J_n@f$.
     *
     * @param M @f$\mathcal C_{imkl}\Delta F^{-1}_{ql}\Delta F^{-1}_{jm}@f$.
     * @param tau Kirchhoff stress.
     * @param dF_inverse @f$\Delta F^{-1}@f$.
     * @param previous_jacobian @f$J_n@f$.
     */
    static Tensor<4, dim>
    tangent(const Tensor<4, 3>          &M,
            const SymmetricTensor<2, 3> &tau,
            const Tensor<2, dim>        &dF_inverse,
            const double                 previous_jacobian)
    {
      // A = (A V^n) / V^n: the product with V^0 replaced by 1 / J_n.
      return tangent_times_volume(M, tau, dF_inverse, 1. / previous_jacobian);
    }

    /**
     * @brief @f$\tilde P\,V^n = \tau\,\Delta F^{-T} V^0@f$, the stress
     * the assembly integrates: with @f$V^n = J_n V^0@f$ the @f$J_n@f$ of
     * @f$\tilde P@f$ cancels, so it is never formed.
     *
     * @param tau Kirchhoff stress.
     * @param dF_inverse @f$\Delta F^{-1}@f$.
     * @param initial_volume @f$V^0@f$.
     */
    static Tensor<2, dim>
    stress_times_volume(const SymmetricTensor<2, 3> &tau,
                        const Tensor<2, dim>        &dF_inverse,
                        const double                 initial_volume)
    {
      return stress(tau, dF_inverse, 1.) * initial_volume;
    }

    /**
     * @brief @f$A\,V^n = (M_{ijkq} - \tau_{im}\Delta F^{-1}_{qm}
     * \Delta F^{-1}_{jk})\,V^0@f$ (as for stress_times_volume(), @f$J_n@f$
     * cancels).
     *
     * @param M The material part (Material::pulled_back_tangent()).
     * @param tau Kirchhoff stress.
     * @param dF_inverse @f$\Delta F^{-1}@f$.
     * @param initial_volume @f$V^0@f$.
     */
    static Tensor<4, dim>
    tangent_times_volume(const Tensor<4, 3>          &M,
                         const SymmetricTensor<2, 3> &tau,
                         const Tensor<2, dim>        &dF_inverse,
                         const double                 initial_volume)
    {
      Tensor<2, dim> T; // V^0 tau dFinv^T
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int q = 0; q < dim; ++q)
          {
            for (unsigned int m = 0; m < dim; ++m)
              T[i][q] += tau[i][m] * dF_inverse[q][m];
            T[i][q] *= initial_volume;
          }
      Tensor<4, dim> A;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int q = 0; q < dim; ++q)
              A[i][j][k][q] =
                initial_volume * M[i][j][k][q] - T[i][q] * dF_inverse[j][k];
      return A;
    }

    /**
     * @brief Axisymmetry: the hoop entries of @f$A\,V^n@f$ (HoopTangent)
     * from the material part of the whole 3x3 tangent, @p M (computed with
     * all three components): @f$A_{ij\theta\theta} = M_{ij\theta\theta}
     * @f$, @f$A_{\theta\theta kq} = M_{\theta\theta kq}@f$ and
     * @f$A_{\theta\theta\theta\theta} = M_{\theta\theta\theta\theta}
     * - \tau_{\theta\theta}/\Delta F_{\theta\theta}^2@f$, each times
     * @f$V^0@f$ (the geometric term of the general formula vanishes where an
     * index pair mixes the plane and the hoop).
     *
     * @param M The material part (Material::pulled_back_tangent()).
     * @param tau Kirchhoff stress.
     * @param hoop_increment @f$\Delta F_{\theta\theta}@f$.
     * @param initial_volume @f$V^0@f$.
     */
    static HoopTangent<dim>
    hoop_tangent_times_volume(const Tensor<4, 3>          &M,
                              const SymmetricTensor<2, 3> &tau,
                              const double                 hoop_increment,
                              const double                 initial_volume)
    {
      HoopTangent<dim> hoop;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            hoop.in_plane_by_hoop[i][j] = initial_volume * M[i][j][2][2];
            hoop.hoop_by_in_plane[i][j] = initial_volume * M[2][2][i][j];
          }
      hoop.hoop_by_hoop =
        initial_volume *
        (M[2][2][2][2] - tau[2][2] / (hoop_increment * hoop_increment));
      return hoop;
    }
  };
} // namespace impm

#endif
