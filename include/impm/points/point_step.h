#ifndef impm_points_point_step_h
#define impm_points_point_step_h

#include <deal.II/base/tensor.h>

#include <deal.II/particles/particle_accessor.h>
#include <deal.II/particles/particle_handler.h>

#include <impm/basis/basis_functions.h>
#include <impm/mechanics/material.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief What one material point needs during one load step: its support
   * on the start-of-step grid (fixed during the step) and the state of the
   * current Newton iterate.
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
    /** Axisymmetry only: the hoop stretch of the current iterate,
     *  @f$\Delta F_{\theta\theta} = 1 + \sum_v \bar N_{\theta,v}
     *  \Delta u_{v,r}@f$, the average of @f$1 + \Delta u_r / r^n@f$ over
     *  the point's ring (1 otherwise). It maps the hoop force as
     *  deformation_increment_inverse maps the gradients. */
    double hoop_increment = 1.;
    /** Axisymmetry only: the hoop stretch the material sees,
     *  hoop_increment, or with F-bar its share of the patch's volume change
     *  (FBar; 1 otherwise). */
    double material_hoop_increment = 1.;
    /** Initial volume @f$V_p^0@f$ (in axisymmetry that of its ring). */
    double initial_volume;
    /** The point's material (of its body). */
    const Material *material;
    /** Constitutive result of the current iterate. */
    ConstitutiveUpdate update;

    /**
     * @brief The point's own displacement for the nodal displacements
     * @p increment (local DoFs): the weights' interpolation, plus in
     * axisymmetric GIMP PointSupport::radial_offset times the radial
     * gradient (the weights interpolate to the ring's centroid).
     */
    template <typename VectorType>
    Tensor<1, dim>
    displacement(const VectorType &increment) const
    {
      Tensor<1, dim> u;
      for (unsigned int v = 0; v < support.n_nodes; ++v)
        {
          const double weight = support.weights[v] +
                                support.radial_offset * support.gradients[v][0];
          for (unsigned int i = 0; i < dim; ++i)
            u[i] += weight * increment.local_element(dofs[v * dim + i]);
        }
      return u;
    }

    /**
     * @brief The increment the material sees, 3x3: deformation_increment
     * with the out-of-plane stretch material_hoop_increment (1 in plane
     * strain).
     */
    Tensor<2, 3>
    full_deformation_increment() const
    {
      Tensor<2, 3> full;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          full[i][j] = deformation_increment[i][j];
      if constexpr (dim == 2)
        full[2][2] = material_hoop_increment;
      return full;
    }
  };



  /**
   * @brief The per-point data of one load step (PointStep) for this
   * process's points: by index for the loops over the step's points (the
   * assembly groups, the couplings' patches and probes) and from the
   * particle for the loops over the particles (the stress update, the
   * end of the step), so that no loop relies on visiting the particles in
   * the order in which the steps were made.
   *
   * The particle's local index (ParticleAccessor::get_local_index()) is
   * stable while the particles stay where they are, that is for the whole
   * load step: reinit() must follow every sort of the particles.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class PointSteps
  {
  public:
    /** @brief The iterators over the steps. */
    using iterator = typename std::vector<PointStep<dim>>::iterator;
    /** @brief The constant iterators over the steps. */
    using const_iterator = typename std::vector<PointStep<dim>>::const_iterator;

    /**
     * @brief One step for each point of @p particles (in their iteration
     * order, which is the order of the indices), with the map from the
     * particles' local indices.
     */
    void
    reinit(const Particles::ParticleHandler<dim> &particles)
    {
      steps.resize(particles.n_locally_owned_particles());
      // The largest local index, from the particles themselves (deal.II's
      // get_max_local_particle_index() is not refreshed by every change of
      // the particles, a repartition for one).
      unsigned int n_indices = 0;
      for (const auto &particle : particles)
        n_indices =
          std::max<unsigned int>(n_indices, particle.get_local_index() + 1);
      index_of_particle.assign(n_indices,
                               std::numeric_limits<unsigned int>::max());
      unsigned int p = 0;
      for (const auto &particle : particles)
        index_of_particle[particle.get_local_index()] = p++;
    }

    /** @brief The number of points. */
    std::size_t
    size() const
    {
      return steps.size();
    }

    /** @brief The step of point @p p. */
    PointStep<dim> &
    operator[](const std::size_t p)
    {
      return steps[p];
    }

    /** @brief The step of point @p p. */
    const PointStep<dim> &
    operator[](const std::size_t p) const
    {
      return steps[p];
    }

    /** @brief The index of the step of @p particle. */
    unsigned int
    index_of(const Particles::ParticleAccessor<dim> &particle) const
    {
      const unsigned int p = index_of_particle[particle.get_local_index()];
      Assert(p < steps.size(), ExcInternalError());
      return p;
    }

    /** @brief The step of @p particle. */
    PointStep<dim> &
    of(const Particles::ParticleAccessor<dim> &particle)
    {
      return steps[index_of(particle)];
    }

    /** @brief The step of @p particle. */
    const PointStep<dim> &
    of(const Particles::ParticleAccessor<dim> &particle) const
    {
      return steps[index_of(particle)];
    }

    /** @brief The first step. */
    iterator
    begin()
    {
      return steps.begin();
    }

    /** @brief The end of the steps. */
    iterator
    end()
    {
      return steps.end();
    }

    /** @brief The first step. */
    const_iterator
    begin() const
    {
      return steps.begin();
    }

    /** @brief The end of the steps. */
    const_iterator
    end() const
    {
      return steps.end();
    }

    /** @brief The memory the steps hold, in bytes. */
    std::size_t
    memory_consumption() const
    {
      return steps.capacity() * sizeof(PointStep<dim>) +
             index_of_particle.capacity() * sizeof(unsigned int);
    }

    /** @brief Free the memory (after a converged step). */
    void
    release()
    {
      steps.clear();
      steps.shrink_to_fit();
      index_of_particle.clear();
      index_of_particle.shrink_to_fit();
    }

  private:
    /** The steps, by index. */
    std::vector<PointStep<dim>> steps;
    /** The index of each particle's step, by the particle's local index. */
    std::vector<unsigned int> index_of_particle;
  };
} // namespace impm

#endif
