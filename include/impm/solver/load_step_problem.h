#ifndef impm_solver_load_step_problem_h
#define impm_solver_load_step_problem_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <impm/assembly/assembler.h>
#include <impm/assembly/ghost_stabilisation.h>
#include <impm/contact/rigid_contact.h>
#include <impm/grid/background_grid.h>
#include <impm/solver/linear_solver.h>
#include <impm/solver/newton_solver.h>
#include <impm/system/load_step_system.h>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The equilibrium of one load step as a NonlinearProblem: the
   * displacement increment from the start of the step is the unknown, the
   * residual is f_ext - f_int on the DoFs of the linear system. Rigid
   * bodies pushed by a force add their displacement components as
   * unknowns, with the balance of their forces as equations (a bordered
   * system, solve_bordered()).
   *
   * It owns the nodal vectors of the step and times its phases ("stress
   * update", "assembly", "linear solve") in the solver's TimerOutput.
   */
  template <int dim>
  class LoadStepProblem : public NonlinearProblem
  {
  public:
    /**
     * @brief The problem over the parts of a run.
     * @param ghost_stabilisation May be nullptr (no stabilisation).
     * @param rigid_contact May be nullptr (no rigid bodies); its begin()
     *   is the caller's, before begin().
     * @param f_bar May be nullptr (no F-bar); with its cell pressure unknowns
     *   their equations join the residual and the Newton corrections.
     */
    LoadStepProblem(const BackgroundGrid<dim>     &grid,
                    LoadStepSystem<dim>           &system,
                    Assembler<dim>                &assembler,
                    const GhostStabilisation<dim> *ghost_stabilisation,
                    RigidContact<dim>             *rigid_contact,
                    FBar<dim>                     *f_bar,
                    LinearSolver                  &linear_solver,
                    TimerOutput                   &timer);

    /**
     * @brief Size the nodal vectors for the grid's current DoF partition
     * (after a repartition).
     */
    void
    reinit_vectors();

    /**
     * @brief Start a step from load factor @p start to @p target: the
     * increment is zero but on the prescribed faces, which move by their
     * share; the external force is that of @p target.
     */
    void
    begin(const double start, const double target);

    Residual
    evaluate_residual() override;

    void
    assemble_matrix() override;

    LinearSolveReport
    solve_and_update(const double relative_tolerance,
                     const bool   estimate_condition) override;

    /**
     * @brief The largest displacement of a point in the current increment,
     * in cells (the largest over directions of |u_d| / h_d).
     */
    double
    max_point_increment() const;

    /**
     * @brief Compare every matrix that assemble_matrix() makes with central
     * differences of the internal force (Testing/Check tangent).
     */
    void
    check_tangents(const bool check)
    {
      checks_tangent = check;
    }

    /**
     * @brief The largest relative difference found by the tangent checks
     * since the last call (negative: none), and start again.
     */
    double
    take_tangent_difference()
    {
      const double difference = tangent_difference;
      tangent_difference      = -1.;
      return difference;
    }

    /**
     * @brief The number of matrix columns the tangent checks since the
     * last call left out because the perturbation changed a contact's
     * state (a kink of the contact force lies within it), and start again.
     */
    unsigned int
    take_tangent_columns_across_kinks()
    {
      const unsigned int n         = tangent_columns_across_kinks;
      tangent_columns_across_kinks = 0;
      return n;
    }

    /** @brief The displacement increment of the current iterate. */
    const NodalVector &
    increment() const
    {
      return displacement_increment;
    }

    /** @brief The reactions of the current iterate, per face and component,
     *  balanced with the load and @p rigid_body_force (the material's
     *  force on the rigid bodies). */
    typename BackgroundGrid<dim>::Reactions
    reactions(const Tensor<1, dim> &rigid_body_force) const
    {
      return grid.compute_reactions(internal_force,
                                    external_force,
                                    rigid_body_force);
    }

  private:
    /** @brief Whether rigid bodies pushed by a force add unknowns. */
    bool
    has_unknowns() const
    {
      return rigid_contact != nullptr && !rigid_contact->unknowns().empty();
    }

    const BackgroundGrid<dim>     &grid;
    LoadStepSystem<dim>           &system;
    Assembler<dim>                &assembler;
    const GhostStabilisation<dim> *ghost_stabilisation;
    RigidContact<dim>             *rigid_contact;
    /** F-bar, or nullptr; its cell pressures, if any, are unknowns here. */
    FBar<dim>    *f_bar;
    LinearSolver &linear_solver;
    TimerOutput  &timer;

    /** Displacement increment of the step (full numbering, ghosted). */
    NodalVector displacement_increment;
    /** Internal and external nodal forces (full numbering). */
    NodalVector internal_force;
    NodalVector external_force;
    /** Norm of the external force on the system's DoFs. */
    double external_force_norm = 0.;

    /**
     * The largest difference, over the matrix's entries, between the
     * assembled matrix and central differences of the internal force,
     * relative to the largest entry. Perturbs each system DoF in turn (on
     * its owner; all processes take part) and restores the iterate. A
     * column whose perturbation changes a rigid contact's state is left
     * out and counted (tangent_columns_across_kinks).
     * Collective.
     */
    double
    tangent_difference_by_central_differences();

    /** The residual of the rigid bodies' unknowns (RigidContact::
     *  unknowns()) at the current iterate. */
    Vector<double> unknown_residual;
    /** The matrix's blocks that couple the bodies' unknowns with the
     *  DoFs (in the system's numbering) and with each other, at the last
     *  assemble_matrix(). */
    std::vector<TrilinosWrappers::MPI::Vector> coupling_columns, coupling_rows;
    FullMatrix<double>                         coupling_corner;

    /**
     * @brief The Newton correction of the bordered system of the DoFs and
     * the bodies' unknowns, by block elimination: with the displacement
     * block K, the coupling columns B, rows C and corner D, solve K Y = B
     * and K z = r with one factorisation (or preconditioner), then the
     * unknowns from (D - C Y) dw = r_w - C z, and du = z - Y dw. A body
     * that touches no material (a zero corner) fails the solve with a
     * line naming it.
     */
    LinearSolveReport
    solve_bordered(const double relative_tolerance,
                   const bool   estimate_condition);

    /**
     * @brief Add the linear solve's solution to the displacement increment
     * and, with F-bar's cell pressures, to them.
     */
    void
    add_solution();

    /** Whether assemble_matrix() checks its matrix. */
    bool checks_tangent = false;
    /** The largest difference of the checks (negative: none). */
    double tangent_difference = -1.;
    /** Columns the checks left out: their perturbation changed a
     *  contact's state. */
    unsigned int tangent_columns_across_kinks = 0;
  };
} // namespace impm

#endif
