#ifndef impm_mechanics_equilibrium_forms_h
#define impm_mechanics_equilibrium_forms_h

#include <deal.II/base/tensor.h>

#include <impm/mechanics/material.h>
#include <impm/mechanics/pulled_back_stress.h>

namespace impm
{
  using namespace dealii;

  /**
   * @brief One material point's integrands in the previously converged
   * statement of equilibrium (the paper's eq. 9-10; formulation note,
   * section 3): the stress @f$\tilde P V^n@f$ and the tangent
   * @f$A V^n@f$ are contracted with the start-of-step gradients as they
   * are, and the model differentiates its stress with respect to
   * @f$\Delta F@f$ directly (Material::pulled_back_tangent()).
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct PreviouslyConvergedForm
  {
    /**
     * @brief The stress that multiplies the gradients in the nodal forces,
     * @f$\tilde P V^n = \tau \Delta F^{-T} V^0@f$.
     */
    static Tensor<2, dim>
    force_stress(const ConstitutiveUpdate &update,
                 const Tensor<2, dim>     &dF_inverse,
                 const double              initial_volume)
    {
      return PulledBackStress<dim>::stress_times_volume(update.kirchhoff_stress,
                                                        dF_inverse,
                                                        initial_volume);
    }

    /**
     * @brief The tangent that multiplies the gradients on both sides in the
     * stiffness, @f$A V^n@f$.
     */
    static Tensor<4, dim>
    tangent(const Material           &material,
            const ConstitutiveUpdate &update,
            const Tensor<2, dim>     &dF_inverse,
            const double              initial_volume)
    {
      Tensor<4, 3> material_part;
      material.pulled_back_tangent(update,
                                   dim,
                                   PulledBackStress<dim>::embed(dF_inverse),
                                   material_part);
      return PulledBackStress<dim>::tangent_times_volume(
        material_part, update.kirchhoff_stress, dF_inverse, initial_volume);
    }

    /**
     * @brief Axisymmetry: the in-plane tangent @f$A V^n@f$ (returned) and
     * its hoop entries (@p hoop), from the material's whole 3x3 pulled-back
     * tangent with @f$\Delta F_{\theta\theta}@f$ = @p hoop_increment.
     */
    static Tensor<4, dim>
    axisymmetric_tangent(const Material           &material,
                         const ConstitutiveUpdate &update,
                         const Tensor<2, dim>     &dF_inverse,
                         const double              hoop_increment,
                         const double              initial_volume,
                         HoopTangent<dim>         &hoop)
    {
      Tensor<2, 3> full_inverse = PulledBackStress<dim>::embed(dF_inverse);
      if constexpr (dim == 2)
        full_inverse[2][2] = 1. / hoop_increment;
      Tensor<4, 3> material_part;
      material.pulled_back_tangent(update, 3, full_inverse, material_part);
      hoop = PulledBackStress<dim>::hoop_tangent_times_volume(
        material_part, update.kirchhoff_stress, hoop_increment, initial_volume);
      return PulledBackStress<dim>::tangent_times_volume(
        material_part, update.kirchhoff_stress, dF_inverse, initial_volume);
    }

    /**
     * @brief Axisymmetry: the hoop force's factor on the start-of-step hoop
     * weights @f$\bar N_v@f$ (the averages of @f$N_v / r^n@f$),
     * @f$\tilde P_{\theta\theta} V^n = \tau_{\theta\theta} V^0 /
     * \Delta F_{\theta\theta}@f$.
     */
    static double
    hoop_force_stress(const ConstitutiveUpdate &update,
                      const double              hoop_increment,
                      const double              initial_volume)
    {
      return update.kirchhoff_stress[2][2] / hoop_increment * initial_volume;
    }

    /**
     * @brief Axisymmetry: what maps the statement's hoop weights to the
     * current configuration, @f$1/\Delta F_{\theta\theta}@f$ (the
     * weights are the start-of-step ones).
     */
    static double
    hoop_map(const double hoop_increment)
    {
      return 1. / hoop_increment;
    }
  };

  /**
   * @brief One material point's integrands in the updated Lagrangian
   * statement (the paper's eq. 7-8; formulation note, section 4): the
   * Cauchy stress over @f$V^{n+1}@f$, @f$\sigma V^{n+1} = \tau V^0@f$, and
   * the spatial tangent, contracted with the gradients mapped to the current
   * configuration, map_gradients(), in every iteration.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  struct UpdatedLagrangianForm
  {
    /**
     * @brief @f$\partial S/\partial x_m = \partial S/\partial \tilde x_j
     * \,\Delta F^{-1}_{jm}@f$ for @p n_nodes gradients.
     */
    static void
    map_gradients(const Tensor<1, dim> *gradients,
                  const unsigned int    n_nodes,
                  const Tensor<2, dim> &dF_inverse,
                  Tensor<1, dim>       *mapped_gradients)
    {
      for (unsigned int v = 0; v < n_nodes; ++v)
        mapped_gradients[v] = gradients[v] * dF_inverse;
    }

    /**
     * @brief The stress that multiplies the mapped gradients in the nodal
     * forces, @f$\sigma V^{n+1} = \tau V^0@f$.
     */
    static Tensor<2, dim>
    force_stress(const ConstitutiveUpdate &update,
                 const Tensor<2, dim> & /*dF_inverse*/,
                 const double initial_volume)
    {
      Tensor<2, dim> stress;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          stress[i][j] = update.kirchhoff_stress[i][j] * initial_volume;
      return stress;
    }

    /**
     * @brief The spatial tangent over the current volume,
     * @f$a V^{n+1} = (\mathcal C_{ijkl} - \tau_{il}\delta_{jk}) V^0@f$.
     */
    static Tensor<4, dim>
    tangent(const Material           &material,
            const ConstitutiveUpdate &update,
            const Tensor<2, dim> & /*dF_inverse*/,
            const double initial_volume)
    {
      Tensor<4, 3> C;
      material.tangent(update, dim, C);
      Tensor<4, dim> a;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              a[i][j][k][l] = (C[i][j][k][l] -
                               (j == k ? update.kirchhoff_stress[i][l] : 0.)) *
                              initial_volume;
      return a;
    }

    /**
     * @brief Axisymmetry: the in-plane spatial tangent @f$a V^{n+1}@f$
     * (returned, as tangent()) and its hoop entries (@p hoop) from the
     * material's whole 3x3 spatial tangent:
     * @f$a_{ij\theta\theta} = \mathcal C_{ij\theta\theta}@f$,
     * @f$a_{\theta\theta kl} = \mathcal C_{\theta\theta kl}@f$ and
     * @f$a_{\theta\theta\theta\theta} = \mathcal C_{\theta\theta\theta
     * \theta} - \tau_{\theta\theta}@f$, each times @f$V^0@f$ (the
     * geometric term @f$\tau_{il}\delta_{jk}@f$ vanishes where an index
     * pair mixes the plane and the hoop). They multiply the hoop weights
     * mapped to the current configuration, @f$\bar N_v /
     * \Delta F_{\theta\theta}@f$ (the averages of @f$N_v / r^{n+1}@f$).
     */
    static Tensor<4, dim>
    axisymmetric_tangent(const Material           &material,
                         const ConstitutiveUpdate &update,
                         const Tensor<2, dim> & /*dF_inverse*/,
                         const double /*hoop_increment*/,
                         const double      initial_volume,
                         HoopTangent<dim> &hoop)
    {
      Tensor<4, 3> C;
      material.tangent(update, 3, C);
      Tensor<4, dim> a;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          {
            hoop.in_plane_by_hoop[i][j] = C[i][j][2][2] * initial_volume;
            hoop.hoop_by_in_plane[i][j] = C[2][2][i][j] * initial_volume;
            for (unsigned int k = 0; k < dim; ++k)
              for (unsigned int l = 0; l < dim; ++l)
                a[i][j][k][l] =
                  (C[i][j][k][l] -
                   (j == k ? update.kirchhoff_stress[i][l] : 0.)) *
                  initial_volume;
          }
      hoop.hoop_by_hoop =
        (C[2][2][2][2] - update.kirchhoff_stress[2][2]) * initial_volume;
      return a;
    }

    /**
     * @brief Axisymmetry: the hoop force's factor on the mapped hoop
     * weights, @f$\sigma_{\theta\theta} V^{n+1} = \tau_{\theta\theta}
     * V^0@f$.
     */
    static double
    hoop_force_stress(const ConstitutiveUpdate &update,
                      const double /*hoop_increment*/,
                      const double initial_volume)
    {
      return update.kirchhoff_stress[2][2] * initial_volume;
    }

    /**
     * @brief Axisymmetry: the mapped hoop weights are those of the current
     * configuration already: 1.
     */
    static double
    hoop_map(const double /*hoop_increment*/)
    {
      return 1.;
    }
  };

  /**
   * @brief Add one point's nodal forces, @f$f_v += S\,\nabla S_v@f$, to
   * @p forces (dim entries per node).
   */
  template <int dim>
  inline void
  add_point_forces(const Tensor<2, dim> &stress,
                   const Tensor<1, dim> *gradients,
                   const unsigned int    n_nodes,
                   double               *forces)
  {
    for (unsigned int v = 0; v < n_nodes; ++v)
      {
        const Tensor<1, dim> force = stress * gradients[v];
        for (unsigned int i = 0; i < dim; ++i)
          forces[v * dim + i] += force[i];
      }
  }

} // namespace impm

#endif
