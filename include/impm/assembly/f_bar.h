#ifndef impm_assembly_f_bar_h
#define impm_assembly_f_bar_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <impm/coupling/coupling.h>
#include <impm/grid/background_grid.h>
#include <impm/points/material_points.h>
#include <impm/points/point_step.h>
#include <impm/system/dense_block_adder.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

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
   * (d = 2 in plane strain: the out-of-plane stretch stays one; d = 3 in
   * axisymmetry, where @f$\Delta J_p@f$ holds the hoop stretch
   * @f$\Delta F_{\theta\theta}@f$ and the material's hoop stretch is
   * scaled with the in-plane increment). The
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
   * doc/formulation.md, "F-bar", for the derivation). In axisymmetry
   * @f$D_p@f$ gains the hoop row @f$D_{\theta,p}@f$ (the hoop force's
   * response to a uniform dilatation), @f$a_{v0}@f$ the term @f$\bar
   * N_{\theta,v} D_{\theta}@f$ and @f$b_{w0}@f$ the term @f$\Delta J_q
   * \bar N_{\theta,w} / \Delta F_{\theta\theta}@f$, with the hoop
   * weights @f$\bar N_\theta@f$; the point's hoop tangent
   * (HoopTangent) gains the per-point term. With cell pressure unknowns
   * the mean stress is the three-dimensional one, and @f$\tilde t@f$ has
   * a hoop entry.
   *
   * <b>Cell pressure unknowns</b> (`Material points/Cell pressure
   * unknowns`). Plain F-bar gives the points of a patch one volume change,
   * so where their plastic dilatancy differs their elastic volumes, and
   * with them their pressures, part: a frictional material's strength
   * follows the pressure, and the points that dilate most lose it. With
   * pressure unknowns each patch has one pressure @f$p_c@f$, an unknown of
   * the linear system (Q1/P0 displacement-pressure, the pressure condensed
   * into nothing else): each point takes the volume change
   * @f$\Delta J^*_p@f$ at which its in-plane mean Kirchhoff stress
   * @f$\pi_p@f$ is @f$p_c@f$ (a scalar Newton solve around its return
   * map), and the patch's equation is that its points' volume is the
   * kinematic one,
   * @f[
   *   R_c = \frac{E}{\hat h}\sum_p V_p^n\,(\Delta J^*_p - \Delta J_p)
   *     + \frac{\beta\,V_{cell}}{\hat h}\sum_n (p_c - p_n) = 0,
   * @f]
   * with @f$E@f$ the body's Young's modulus and @f$\hat h =
   * V_{cell}^{1/d}@f$ (the row is a force), and the pressure-jump
   * stabilisation of Q1/P0 (Kechkar and Silvester 1992) over the patches
   * of the same body in the face neighbours of the patch's cell, factor
   * @f$\beta@f$ (`Material points/Pressure jump stabilisation`, 0: none).
   * The tangent follows from @f$d\pi_p = \tilde t_p : G_p + k_p\,
   * d\ln\Delta J^*_p = dp_c@f$, with @f$t_{kl} = \frac1d \sum_i
   * \mathcal C_{iikl}@f$, @f$k_p = \mathrm{tr}\,t/d@f$ and
   * @f$\tilde t = t - k_p I@f$ (doc/formulation.md, "F-bar").
   *
   * A scene that does not ask for F-bar creates none of this.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class FBar : public Coupling<dim>
  {
  public:
    /** @brief The coupling of a scene (Material points/F-bar). */
    explicit FBar(const CouplingInputs<dim> &inputs);

    /** @brief make_patches(): the pressure unknowns' rows. */
    unsigned int
    prepare(const MaterialPoints<dim> &material_points,
            const LoadStepSystem<dim> &system,
            const std::vector<bool>   &touched) override;

    /** @brief set_up_patches() from @p rows.first, and patch_rows(). */
    void
    setup(const MaterialPoints<dim>                         &material_points,
          const LoadStepSystem<dim>                         &system,
          const CouplingRows                                &rows,
          std::vector<std::vector<types::global_dof_index>> &blocks) override;

    /** @brief reset_pressure_unknowns() (with pressure unknowns). */
    void
    begin_attempt(const MaterialPoints<dim> &material_points,
                  const LoadStepSystem<dim> &system,
                  const StepSpan            &span) override;

    /** @brief True: F-bar sets the points' volume changes. */
    bool
    sets_point_volumes() const override;

    /** @brief With pressure unknowns equalise_pressures(), else average()
     *  and every point's return map. */
    bool
    update_stresses(
      PointSteps<dim>                         &point_steps,
      const std::function<bool(unsigned int)> &update_point) override;

    /** @brief add_patch_stiffness(). */
    bool
    add_matrix(const PointGradients<dim>      &gradients,
               const LoadStepSystem<dim>      &system,
               TrilinosWrappers::SparseMatrix &matrix) override;

    /** @brief pressure_residuals() (with pressure unknowns). */
    void
    add_row_residuals(std::vector<std::pair<types::global_dof_index, double>>
                        &residuals) override;

    /** @brief add_to_pressure_unknowns() (with pressure unknowns). */
    void
    add_solution(const TrilinosWrappers::MPI::Vector &solution) override;

    /** @brief perturb_pressure_unknown() (with pressure unknowns). */
    double
    perturb_row(const types::global_dof_index row,
                const double                  amount) override;

    /** @brief With pressure unknowns: a direct solver (GMRES with the
     *  smoothed-aggregation AMG fails on their rows: on the Mohr-Coulomb
     *  footing at h = 0.125 m 61 of 189 GMRES solves failed and went to
     *  KLU, 10 times the run time). */
    bool
    needs_direct_solver() const override;

    /** @brief With pressure unknowns: they are rows of the load step's
     *  system, which an explicit step does not solve (their pressures would
     *  stay at the start's). */
    std::string
    explicit_step_conflict() const override;

    /** @brief With pressure unknowns, what the linear solver does with
     *  them. */
    std::vector<std::string>
    notes(const Parameters::LinearSolverType linear_solver) const override;

    /** @brief description(). */
    std::vector<std::string>
    descriptions() const override;

    /**
     * @brief Constructor.
     * @param grid The background grid (cells and their neighbours).
     * @param pressure_unknowns Whether each patch's pressure is an unknown
     *   (else its volume change is the points' mean).
     * @param stabilisation The pressure-jump factor @f$\beta@f$ (pressure
     *   unknowns only).
     */
    FBar(const BackgroundGrid<dim> &grid,
         const bool                 pressure_unknowns,
         const double               stabilisation);

    /**
     * @brief Whether the patches' pressures are unknowns of the linear
     * system.
     */
    bool
    has_pressure_unknowns() const
    {
      return pressure_unknowns;
    }

    /**
     * @brief Group this step's points into patches (body and cell at the
     * start of the step). Returns the number of pressure unknowns this
     * process owns: one per patch with has_pressure_unknowns(), else none.
     * Called by prepare(), before the system is numbered.
     */
    unsigned int
    make_patches(const MaterialPoints<dim> &material_points);

    /**
     * @brief Weigh the patches of make_patches() by their start-of-step
     * volumes and collect each patch's DoFs in the linear system; with
     * pressure unknowns, number them from @p first_pressure_index (this
     * process's, after its nodal rows), start them at the patches' mean
     * stresses and find each patch's neighbours (on other processes too).
     * Called by setup(), once the system's DoFs are numbered.
     * Collective.
     */
    void
    set_up_patches(const MaterialPoints<dim>    &material_points,
                   const LoadStepSystem<dim>    &system,
                   const unsigned int            n_local_dofs,
                   const types::global_dof_index first_pressure_index,
                   const IndexSet               &owned_rows);

    /**
     * @brief The system indices of each patch's blocks (ascending), for
     * the sparsity pattern: its DoFs (and, with pressure unknowns, its
     * pressure) and, with a stabilisation, its pressure and its
     * neighbours'.
     */
    std::vector<std::vector<types::global_dof_index>>
    patch_rows() const;

    /**
     * @brief Replace each point's PointStep::deformation_increment (the
     * true @f$\Delta F_p@f$ on entry, all with positive determinant) by
     * @f$\Delta\bar F_p@f$.
     */
    void
    average(PointSteps<dim> &point_steps);

    /**
     * @brief With pressure unknowns, the stress update of every point: find
     * the volume change at which its mean stress is its patch's pressure
     * and leave the point's PointStep::deformation_increment and update
     * there.
     * @param point_steps The points, with the true @f$\Delta F_p@f$ on
     *   entry (all with positive determinant).
     * @param update_point Runs point p's return map on its
     *   PointStep::deformation_increment; false if the model threw.
     * @return False if a point's return failed or its solve did not
     *   converge (a wild iterate: the Newton iteration fails).
     */
    bool
    equalise_pressures(PointSteps<dim>                         &point_steps,
                       const std::function<bool(unsigned int)> &update_point);

    /**
     * @brief Start a load step's attempt: the pressure unknowns at the
     * patches' start-of-step mean stresses, every point at its own volume.
     */
    void
    reset_pressure_unknowns();

    /**
     * @brief Add the Newton correction @p solution (in the system's
     * numbering) to the pressure unknowns this process owns.
     */
    void
    add_to_pressure_unknowns(const TrilinosWrappers::MPI::Vector &solution);

    /**
     * @brief Perturb the pressure unknown (the pressure over E) with
     * system index @p index by @p amount over h (a strain: as a DoF
     * perturbed by a fraction of the cell size), if this process
     * owns it (the tangent check). Returns that scale, or zero if another
     * process owns it.
     */
    double
    perturb_pressure_unknown(const types::global_dof_index index,
                             const double                  amount);

    /**
     * @brief The patches' equations @f$R_c@f$ at the last stress update, on
     * this process's pressure rows (with the neighbours' contributions
     * from other processes). Collective.
     * @return Pairs (system index, @f$R_c@f$), one per owned patch.
     */
    const std::vector<std::pair<types::global_dof_index, double>> &
    pressure_residuals();

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
     * @param hoop Axisymmetry: the hoop tangent, which gains the F-bar
     *   terms of the hoop row and column (d = 3); nullptr otherwise.
     * @param hoop_force_stress Axisymmetry: the hoop force's factor on the
     *   statement's hoop weights (Coupling::point_tangent()).
     * @param hoop_map Axisymmetry: what maps the statement's hoop weights
     *   to the current configuration (PointGradients::hoop_map()).
     */
    Tensor<4, dim>
    point_tangent(const unsigned int    p,
                  const Tensor<4, dim> &tangent,
                  const Tensor<2, dim> &force_stress,
                  const Tensor<2, dim> &gradient_map,
                  HoopTangent<dim>     *hoop,
                  const double          hoop_force_stress,
                  const double          hoop_map) override;

    /**
     * @brief Add every patch's coupling block to @p matrix.
     * @param point_steps The points of the last stress update.
     * @param gradients The statement's gradients of each point and their
     *   maps (as in point_tangent()).
     * @param matrix The system matrix.
     * @param off_process_rows Its rows owned by other processes.
     */
    void
    add_patch_stiffness(const PointSteps<dim>          &point_steps,
                        const PointGradients<dim>      &gradients,
                        TrilinosWrappers::SparseMatrix &matrix,
                        const OffProcessRows           &off_process_rows);

    /** @brief One line for the run's list of effects. */
    std::string
    description() const;

  private:
    /**
     * @brief add_patch_stiffness() with pressure unknowns: per patch one
     * dense block over its DoFs and its pressure (the pressure's column
     * and the patch's row) and, with a stabilisation, one over its
     * pressure and its neighbours' (its share of their rows).
     */
    void
    add_pressure_stiffness(const PointSteps<dim>          &point_steps,
                           const PointGradients<dim>      &gradients,
                           TrilinosWrappers::SparseMatrix &matrix,
                           const OffProcessRows           &off_process_rows);

    /**
     * @brief Point @p p's terms at a node of its support (the statement's
     * gradient @p gradient, its map @p map; in axisymmetry the statement's
     * hoop weight @p hoop_weight and its map @p hoop_map), with the hoop's:
     * @p stress_part, the force of its dilatation stress, @f$D_p \nabla
     * S_v@f$ (+ @f$\bar N_{\theta,v} D_{\theta}@f$ radially), and @p
     * spatial, the spatial gradient of tr G (+ the hoop weight in the
     * current configuration, @f$\bar N_{\theta,v}@f$ times @p hoop_map).
     * Returns @f$\tilde t@f$ applied to it (pressure unknowns; zero
     * otherwise).
     */
    Tensor<1, dim>
    node_terms(const unsigned int    p,
               const Tensor<1, dim> &gradient,
               const Tensor<2, dim> &map,
               const double          hoop_weight,
               const double          hoop_map,
               Tensor<1, dim>       &stress_part,
               Tensor<1, dim>       &spatial) const;

    /**
     * @brief Number the pressure unknowns from @p first_pressure_index,
     * find each patch's neighbours (their unknowns from their owners for
     * ghost cells) and make each patch's block. Collective.
     */
    void
    set_up_pressure_unknowns(const MaterialPoints<dim>    &material_points,
                             const PointSteps<dim>        &point_steps,
                             const types::global_dof_index first_pressure_index,
                             const IndexSet               &owned_rows);

    /** The grid: cells, neighbours, cell sizes. */
    const BackgroundGrid<dim> &grid;
    /** Whether the patches' pressures are unknowns. */
    const bool pressure_unknowns;
    /** The pressure-jump factor beta. */
    const double stabilisation;
    /** Per patch: its cell, its body, its start-of-step volume. */
    std::vector<typename Triangulation<dim>::active_cell_iterator> patch_cell;
    std::vector<unsigned int>                                      patch_body;
    std::vector<double>                                            patch_volume;
    /** Per patch (pressure unknowns only): the unknown's system index, its
     *  value and its start-of-step value, the body's Young's modulus, the
     *  row scale E V_c / h. */
    std::vector<types::global_dof_index> pressure_index;
    std::vector<double> pressure, start_pressure, modulus, row_scale;
    /** beta V_cell / h. */
    double face_coefficient = 0.;
    /** h = V_cell^(1/d). */
    double cell_length = 1.;
    /** Offsets of each patch's neighbours in neighbour_indices (CSR), and
     *  their pressures' system indices. */
    std::vector<unsigned int>            neighbour_start;
    std::vector<types::global_dof_index> neighbour_indices;
    /** Offsets of each patch's block in block_indices (CSR): the ascending
     *  system indices of its DoFs and its pressure. */
    std::vector<unsigned int>            block_start;
    std::vector<types::global_dof_index> block_indices;
    /** Offsets of each patch's stabilisation block in jump_indices (CSR;
     *  empty without neighbours): its pressure's and its neighbours'
     *  system indices, ascending. */
    std::vector<unsigned int>            jump_start;
    std::vector<types::global_dof_index> jump_indices;
    /** Per point (pressure unknowns only): ln of its volume change, that
     *  volume change, and its mean stress's response to it (k) and to the
     *  isochoric part of a perturbation (t~). */
    std::vector<double>         log_volume, point_volume, bulk_response;
    std::vector<Tensor<2, dim>> pressure_response;
    /** Per point (pressure unknowns, axisymmetry): t~'s hoop entry. */
    std::vector<double> pressure_hoop_response;
    /** The equations' contributions, to owned and neighbours' rows. */
    TrilinosWrappers::MPI::Vector pressure_rows;
    /** The owned rows of the last pressure_residuals(). */
    std::vector<std::pair<types::global_dof_index, double>> residuals;
    /** The dense block of the current patch. */
    std::vector<double> block;

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
    /** Per point, axisymmetry only: the true hoop stretch of the last
     *  average() and the hoop row of D of the last point_tangent(). */
    std::vector<double> hoop_stretch, dilatation_hoop_stress;
    /** @brief The directions a patch's volume change is shared among:
     *  dim, or 3 in axisymmetry (the hoop). */
    unsigned int
    n_volume_directions() const
    {
      return grid.cartesian().axisymmetric ? 3 : dim;
    }
    /** Per local DoF: its position in the current patch, or -1. */
    std::vector<int> position_in_patch;
    /** The vectors a and b of the current patch. */
    std::vector<double> a, b;
    /** Adds the patch blocks. */
    DenseBlockAdder block_adder;
  };



} // namespace impm

#endif
