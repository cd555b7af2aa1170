#ifndef impm_assembly_f_bar_h
#define impm_assembly_f_bar_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <impm/assembly/dense_block_adder.h>
#include <impm/points/material_points.h>
#include <impm/system/point_step.h>

#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  template <int dim>
  class LoadStepSystem;

  /**
   * @brief The F-bar treatment of volumetric locking for material points
   * (Coombs, Charlton, Cortis and Augarde 2018, after de Souza Neto, Peric,
   * Dutko and Owen 1996), with its consistent tangent.
   *
   * The points of one body in one cell at the start of the load step form a
   * patch. Each point's deformation gradient increment is scaled so that its
   * volume change is the patch's volume-weighted mean,
   * @f[
   *   \Delta\bar F_p = \left(\frac{\Delta\bar J}{\Delta J_p}\right)^{1/d}
   *   \Delta F_p, \qquad
   *   \Delta\bar J = \frac{\sum_q \Delta J_q V_q^n}{\sum_q V_q^n},
   * @f]
   * (d = 2 in plane strain: the out-of-plane stretch stays one). The
   * material sees @f$\Delta\bar F_p@f$, the point's deformation gradient
   * accumulates it (so the points of a patch keep the patch's true volume),
   * and the equilibrium maps the gradients with the true @f$\Delta F_p@f$:
   * the internal force is @f$\tau(\Delta\bar F_p)\,\Delta F_p^{-T}
   * \nabla\tilde S\, V^0@f$ in both statements of equilibrium.
   *
   * The tangent gains, per point, @f$-\frac1d (D_p \nabla S_v) \otimes
   * \nabla_x S_w@f$ (folded into the point's tangent, which loses its major
   * symmetry) and, per patch, the dense rank-one block
   * @f$\frac{1}{d\,\Delta\bar J} a \otimes b@f$ that couples every pair of
   * nodes the patch's points touch, with @f$a_{vi} = \sum_p (D_p \nabla
   * S_{vp})_i@f$, @f$b_{wk} = \sum_q \frac{V_q^n}{\sum V^n} \Delta J_q
   * (\nabla_x S_{wq})_k@f$ and @f$D_p = V^0\,(\mathcal C : I)\,\Delta
   * F^{-T}@f$ the stress response to a uniform dilatation (see
   * doc/formulation.md, "F-bar", for the derivation).
   *
   * A scene that does not ask for F-bar creates none of this.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class FBar
  {
  public:
    /**
     * @brief Group this step's points into patches (body and cell at the
     * start of the step), weigh them by their start-of-step volumes and
     * collect each patch's DoFs in the linear system. Called by
     * LoadStepSystem::setup() once the system's DoFs are numbered.
     */
    void
    setup(const MaterialPoints<dim> &material_points,
          const LoadStepSystem<dim> &system,
          const unsigned int         n_local_dofs);

    /**
     * @brief The system indices of each patch's DoFs (ascending), for the
     * sparsity pattern.
     */
    std::vector<std::vector<types::global_dof_index>>
    patch_rows() const;

    /**
     * @brief Replace each point's PointStep::deformation_increment (the
     * true @f$\Delta F_p@f$ on entry, all with positive determinant) by
     * @f$\Delta\bar F_p@f$.
     */
    void
    average(std::vector<PointStep<dim>> &point_steps);

    /**
     * @brief The point tangent with the F-bar term of point @p p folded in,
     * @f$A_{ijkq} - \frac1d D_{ij} R^{-1}_{qk}@f$, where @f$D_{ij} =
     * A_{ijkq} R_{kq} + S_{ij}@f$ is kept for add_patch_stiffness().
     * @param p The point's index in the point steps.
     * @param tangent The statement's tangent A (times volume).
     * @param force_stress The statement's force stress S (times volume).
     * @param gradient_map @f$R^{-1}@f$: what maps the statement's
     *   gradients to the current configuration (@f$\Delta F^{-1}@f$ for
     *   start-of-step gradients, the identity for mapped ones).
     */
    Tensor<4, dim>
    point_tangent(const unsigned int    p,
                  const Tensor<4, dim> &tangent,
                  const Tensor<2, dim> &force_stress,
                  const Tensor<2, dim> &gradient_map);

    /**
     * @brief Add every patch's coupling block to @p matrix.
     * @param point_steps The points of the last stress update.
     * @param gradients The statement's gradients of point p.
     * @param gradient_maps As in point_tangent(), of point p.
     * @param matrix The system matrix.
     * @param off_process_rows Its rows owned by other processes.
     */
    template <typename Gradients, typename GradientMaps>
    void
    add_patch_stiffness(const std::vector<PointStep<dim>> &point_steps,
                        const Gradients                   &gradients,
                        const GradientMaps                &gradient_maps,
                        TrilinosWrappers::SparseMatrix    &matrix,
                        const OffProcessRows              &off_process_rows);

    /** @brief One line for the run's list of effects. */
    std::string
    description() const;

  private:
    /** Offsets of each patch's points in patch_points (CSR). */
    std::vector<unsigned int> patch_start;
    /** The points of the patches, patch after patch. */
    std::vector<unsigned int> patch_points;
    /** Per point: its share of its patch's start-of-step volume. */
    std::vector<double> volume_share;
    /** Offsets of each patch's DoFs in patch_dofs (CSR). */
    std::vector<unsigned int> dof_start;
    /** The local (nodal vector) indices of each patch's DoFs in the
     * system, ordered by their system indices. */
    std::vector<unsigned int> patch_dofs;
    /** Their system indices. */
    std::vector<types::global_dof_index> patch_system_indices;
    /** Per point: @f$\Delta J_p@f$ of the last average(). */
    std::vector<double> jacobian;
    /** Per patch: @f$\Delta\bar J@f$ of the last average(). */
    std::vector<double> mean_jacobian;
    /** Per point: D of the last point_tangent(). */
    std::vector<Tensor<2, dim>> dilatation_stress;
    /** Per local DoF: its position in the current patch, or -1. */
    std::vector<int> position_in_patch;
    /** The vectors a and b of the current patch. */
    std::vector<double> a, b;
    /** Adds the patch blocks. */
    DenseBlockAdder block_adder;
  };



  template <int dim>
  template <typename Gradients, typename GradientMaps>
  void
  FBar<dim>::add_patch_stiffness(const std::vector<PointStep<dim>> &point_steps,
                                 const Gradients                   &gradients,
                                 const GradientMaps             &gradient_maps,
                                 TrilinosWrappers::SparseMatrix &matrix,
                                 const OffProcessRows &off_process_rows)
  {
    const unsigned int n_patches = mean_jacobian.size();
    for (unsigned int patch = 0; patch < n_patches; ++patch)
      {
        const unsigned int first_dof = dof_start[patch];
        const unsigned int n_dofs    = dof_start[patch + 1] - first_dof;
        if (n_dofs == 0)
          continue;
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = k;
        a.assign(n_dofs, 0.);
        b.assign(n_dofs, 0.);
        for (unsigned int c = patch_start[patch]; c < patch_start[patch + 1];
             ++c)
          {
            const unsigned int    p      = patch_points[c];
            const PointStep<dim> &step   = point_steps[p];
            const Tensor<1, dim> *g      = gradients(p);
            const Tensor<2, dim> &map    = gradient_maps(p);
            const double          weight = volume_share[p] * jacobian[p];
            for (unsigned int v = 0; v < step.support.n_nodes; ++v)
              {
                const Tensor<1, dim> stress_part = dilatation_stress[p] * g[v];
                const Tensor<1, dim> spatial     = g[v] * map;
                for (unsigned int i = 0; i < dim; ++i)
                  {
                    const int position =
                      position_in_patch[step.dofs[v * dim + i]];
                    if (position < 0)
                      continue;
                    a[position] += stress_part[i];
                    b[position] += weight * spatial[i];
                  }
              }
          }
        for (unsigned int k = 0; k < n_dofs; ++k)
          position_in_patch[patch_dofs[first_dof + k]] = -1;
        const double coefficient = 1. / (dim * mean_jacobian[patch]);
        block_adder.add(
          patch_system_indices.data() + first_dof,
          n_dofs,
          [&](const unsigned int row, const unsigned int column) {
            return coefficient * a[row] * b[column];
          },
          matrix,
          off_process_rows);
      }
  }
} // namespace impm

#endif
