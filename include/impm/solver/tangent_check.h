#ifndef impm_solver_tangent_check_h
#define impm_solver_tangent_check_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <impm/coupling/couplings.h>
#include <impm/grid/background_grid.h>
#include <impm/system/load_step_system.h>

#include <functional>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The blocks of a bordered system that couple the couplings'
   * global unknowns (Coupling::n_global_unknowns()) with the system's rows,
   * all couplings' together.
   */
  struct BorderedBlock
  {
    /** Per global unknown: the derivative of the system's forces with
     *  respect to it (the system's partition). */
    std::vector<TrilinosWrappers::MPI::Vector> columns;
    /** Per global unknown: the derivative of its force with respect to the
     *  system's unknowns. */
    std::vector<TrilinosWrappers::MPI::Vector> rows;
    /** The derivatives of the global unknowns' forces with respect to each
     *  other. */
    FullMatrix<double> corner;
  };

  /** @brief What a tangent check found. */
  struct TangentCheckResult
  {
    /**
     * The largest difference between an entry of the matrix and its
     * central difference, relative to the largest entry of the entry's row
     * (negative: nothing checked). Row by row, so that a small error in a
     * material's block shows beside a stiff contact penalty elsewhere.
     */
    double largest_row_difference = -1.;
    /** The same difference relative to the largest entry of the whole
     *  matrix (the measure before rows: for comparison). */
    double largest_matrix_difference = -1.;
    /** The columns left out because their perturbation changed a
     *  coupling's state (a kink of its force lies within it). */
    unsigned int columns_across_kinks = 0;

    /** @brief Take the worse of this and @p other. */
    void
    merge(const TangentCheckResult &other);
  };

  /**
   * @brief Testing/Check tangent: compares an assembled matrix with central
   * differences of the forces, column by column. Each system unknown is
   * perturbed in turn (on its owner; all processes take part), and each
   * global unknown of the couplings; the forces are the internal force on
   * the nodal rows, the couplings' row residuals on theirs and the global
   * unknowns' forces. The iterate is restored at the end. Test logic
   * only: the Newton problem calls it when the scene asks.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class TangentCheck
  {
  public:
    /**
     * @brief Constructor.
     * @param grid The grid (the cell size sets the perturbation).
     * @param system The load step's system and matrix.
     * @param couplings The scene's couplings.
     */
    TangentCheck(const BackgroundGrid<dim> &grid,
                 const LoadStepSystem<dim> &system,
                 Couplings<dim>            &couplings);

    /**
     * @brief Check the system's matrix and @p border at the iterate @p
     * increment.
     * @param increment The iterate, perturbed one unknown at a time and
     *   restored at the end.
     * @param internal_force The internal force that @p update_forces
     *   updates.
     * @param border The couplings' bordered block at the iterate.
     * @param update_forces Updates the stresses and @p internal_force
     *   (with the couplings' forces, compressed) at the current increment;
     *   false if the iterate is inadmissible.
     * Collective.
     */
    TangentCheckResult
    run(NodalVector                 &increment,
        const NodalVector           &internal_force,
        const std::function<bool()> &update_forces,
        const BorderedBlock         &border) const;

  private:
    /** @brief Compare the system's column @p column (perturbed by @p
     *  perturbation) with its central differences. Collective. */
    template <typename Comparison, typename Evaluate>
    void
    check_system_column(const types::global_dof_index column,
                        const double                  perturbation,
                        NodalVector                  &increment,
                        const BorderedBlock          &border,
                        const Evaluate               &evaluate,
                        Comparison                   &comparison) const;

    /** @brief Compare global unknown @p j's column with its central
     *  differences. Collective. */
    template <typename Comparison, typename Evaluate>
    void
    check_global_column(const unsigned int   j,
                        const double         perturbation,
                        const BorderedBlock &border,
                        const Evaluate      &evaluate,
                        Comparison          &comparison) const;

    /** @brief The result of the comparisons, over all processes.
     *  Collective. */
    template <typename Comparison>
    TangentCheckResult
    conclude(Comparison &comparison) const;

    const BackgroundGrid<dim> &grid;
    const LoadStepSystem<dim> &system;
    Couplings<dim>            &couplings;
  };
} // namespace impm

#endif
