#ifndef impm_solver_load_step_problem_h
#define impm_solver_load_step_problem_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <impm/assembly/assembler.h>
#include <impm/coupling/couplings.h>
#include <impm/grid/background_grid.h>
#include <impm/solver/linear_solver.h>
#include <impm/solver/newton_solver.h>
#include <impm/solver/tangent_check.h>
#include <impm/system/load_step_system.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The nodal state of a converged load step on the step's grid,
   * after the couplings have accepted it and before the points move to its
   * end: what Postprocessor::after_convergence() reads (grid output).
   */
  template <int dim>
  struct ConvergedStep
  {
    /** The step's displacement increment (full numbering, ghosted). */
    const NodalVector &increment;
    /** The internal force with the couplings' forces (full numbering,
     *  owned entries). */
    const NodalVector &internal_force;
    /** The external force of the step's end (full numbering, owned
     *  entries). */
    const NodalVector &external_force;
    /** The points' supports and weights on the step's grid. */
    const PointSteps<dim> &point_steps;
  };

  /**
   * @brief The equilibrium of one load step as a NonlinearProblem: the
   * displacement increment from the start of the step is the unknown, the
   * residual is f_ext - f_int on the DoFs of the linear system, with the
   * scene's couplings' terms (Coupling): their forces, the equations of
   * their rows of unknowns, and their global unknowns (all couplings' in
   * one bordered block, eliminated together: solve_bordered()).
   *
   * It owns the nodal vectors of the step and times its phases ("stress
   * update", "assembly", "linear solve") in the solver's TimerOutput. It
   * names no coupling.
   */
  template <int dim>
  class LoadStepProblem : public NonlinearProblem
  {
  public:
    /**
     * @brief The problem over the parts of a run.
     * @param grid The background grid.
     * @param system The load step's system (numbering, matrix, vectors).
     * @param assembler The stress update, forces and matrix.
     * @param couplings The scene's couplings.
     * @param linear_solver The linear solver.
     * @param timer The solver's phase timer ("stress update", "assembly",
     *   "linear solve").
     */
    LoadStepProblem(const BackgroundGrid<dim> &grid,
                    LoadStepSystem<dim>       &system,
                    Assembler<dim>            &assembler,
                    Couplings<dim>            &couplings,
                    LinearSolver              &linear_solver,
                    TimerOutput               &timer);

    /**
     * @brief Size the nodal vectors for the grid's current DoF partition
     * (after a repartition).
     */
    void
    reinit_vectors();

    /**
     * @brief Start the step @p span: the couplings start their attempt
     * (Coupling::begin_attempt()), the increment is zero but on the
     * prescribed faces, which move by their share of the change of load
     * factor; the external force is that of the step's end.
     */
    void
    begin(const MaterialPoints<dim> &material_points, const StepSpan &span);

    /**
     * @brief The residual of the step's start (the zero increment's
     * internal force, with the forces of the couplings that do not ask
     * for it, minus the external force of load factor
     * @p start_load_factor) for the couplings that ask for it
     * (Coupling::needs_start_residual()); nothing when none does.
     * @return Whether it did: then external_force holds the external force
     * of @p start_load_factor.
     */
    bool
    set_start_residual(const double start_load_factor);

    /** @brief Whether a coupling finds each step's increment itself
     *  (explicit time integration: Couplings::step_solver()). */
    bool
    is_explicit() const
    {
      return couplings.step_solver() != nullptr;
    }

    /**
     * @brief An explicit step, after begin(): the increment from the
     * coupling that finds it, the stresses and forces it gives. No matrix,
     * no Newton iteration: the record has one residual, that of the free
     * DoFs before the inertial force (the inertial force of the step's
     * end is that residual, so the reactions balance by construction).
     * Collective.
     */
    NewtonRecord
    explicit_step();

    Residual
    evaluate_residual() override;

    void
    assemble_matrix() override;

    LinearSolveReport
    solve_and_update(const double relative_tolerance,
                     const bool   estimate_condition) override;

    void
    move_along_last_correction(const double factor) override;

    /**
     * @brief The largest displacement of a point in the current increment,
     * in cells (the largest over directions of |u_d| / h_d), and of the
     * couplings' unknowns.
     */
    double
    max_point_increment() const;

    /**
     * @brief Compare every matrix that assemble_matrix() makes with central
     * differences of the forces (Testing/Check tangent; TangentCheck).
     */
    void
    check_tangents(const bool check)
    {
      checks_tangent = check;
    }

    /**
     * @brief The worst result of the tangent checks since the last call,
     * and start again.
     */
    TangentCheckResult
    take_tangent_check()
    {
      const TangentCheckResult result = tangent_check_result;
      tangent_check_result            = TangentCheckResult();
      return result;
    }

    /** @brief The displacement increment of the current iterate. */
    const NodalVector &
    increment() const
    {
      return displacement_increment;
    }

    /** @brief The step's nodal state at the current iterate, for output
     *  of a converged step (Postprocessor::after_convergence()). */
    ConvergedStep<dim>
    converged_step() const
    {
      return {displacement_increment,
              internal_force,
              external_force,
              system.point_steps};
    }

    /** @brief The reactions of the current iterate, per face and component,
     *  balanced with the load and the couplings' share of it
     *  (Coupling::force_from_material()). */
    typename BackgroundGrid<dim>::Reactions
    reactions() const
    {
      return grid.compute_reactions(internal_force,
                                    external_force,
                                    couplings.force_from_material() +
                                      explicit_inertial_force);
    }

    /** @brief Keep, from the next begin() on, what work_of_loads_and_faces()
     *  needs (the start's external force and residual where they differ
     *  from the end's): a scene that keeps an energy balance. */
    void
    keep_energy_balance()
    {
      keeps_energy = true;
    }

    /**
     * @brief The work done on the material over the converged step by the
     * loads and the prescribed faces, summed over the processes: the
     * increment times the mean of the start's and the end's external force
     * at every DoF, and at the DoFs a face moves, times the mean of the
     * start's and the end's residual (the face's force on the material,
     * internal with the couplings' minus external force). After
     * keep_energy_balance(); the end's forces stand for the start's where
     * the start's were not kept (a load that does not change in the step;
     * a face the scene does not move). Collective.
     */
    double
    work_of_loads_and_faces() const;

  private:
    /** Whether begin() keeps the start's forces (keep_energy_balance()). */
    bool keeps_energy = false;
    /** The external force and the residual of the step's start (kept with
     *  the energy balance, where they may differ from the end's). */
    NodalVector start_external_force, start_residual;
    bool        has_start_external_force = false, has_start_residual = false;

    /** The inertial force of the last explicit step (zero otherwise). */
    Tensor<1, dim> explicit_inertial_force;

    const BackgroundGrid<dim> &grid;
    LoadStepSystem<dim>       &system;
    Assembler<dim>            &assembler;
    Couplings<dim>            &couplings;
    LinearSolver              &linear_solver;
    TimerOutput               &timer;

    /** Displacement increment of the step (full numbering, ghosted). */
    NodalVector displacement_increment;
    /** Internal and external nodal forces (full numbering). */
    NodalVector internal_force;
    NodalVector external_force;
    /** Norm of the external force on the system's DoFs. */
    double external_force_norm = 0.;
    /** The residual's least reference of a step that nothing drives
     *  (no load, no prescribed face moving): the internal force of a
     *  strain of 1e-5 (set in begin(); 0 for a driven step). */
    double unloaded_reference = 0.;
    /** The round-off of the stresses' forces: the internal force of a
     *  strain of 64 machine epsilons (set in begin()). A residual below it
     *  is converged: a stiff body in free flight has round-off stresses
     *  whose forces no iteration lowers, far below any real strain's. */
    double stress_round_off = 0.;
    /** The prescribed faces already reported as moving no material. */
    std::array<bool, 6> warned_faces{};

    /**
     * @brief Report once per face (on standard error) a prescribed grid
     * face that moves no material in the step @p span (no material lies
     * in the cells along it: its reaction is zero from there on), from the
     * DoFs the step's setup found touched (LoadStepSystem::touched()).
     * Collective; nothing in a scene without prescribed faces.
     */
    void
    warn_of_faces_without_material(const StepSpan &span);

    /**
     * @brief The stress update and the internal force with the couplings'
     * forces (compressed) at the current increment; false if the iterate
     * is inadmissible. Collective.
     */
    bool
    update_forces();

    /**
     * @brief The internal force of the last stress update with the
     * couplings' forces (compressed). Collective.
     */
    void
    add_internal_forces();

    /** The couplings' row residuals at the last evaluate_residual(). */
    std::vector<std::pair<types::global_dof_index, double>> row_residuals;
    /** The residual of the global unknowns at the current iterate. */
    Vector<double> global_residual;
    /** The bordered block at the last assemble_matrix(). */
    BorderedBlock border;
    /** The global unknowns' part of the last correction (empty without
     *  global unknowns). */
    Vector<double> last_global_correction;

    /**
     * @brief The Newton correction of the bordered system of the DoFs and
     * the global unknowns, by block elimination: with the system's matrix
     * K, the columns B, rows C and corner D, solve K Y = B and K z = r with
     * one factorisation (or preconditioner), then the unknowns from (D - C
     * Y) dw = r_w - C z, and du = z - Y dw. An unknown with a zero corner
     * (nothing holds it) fails the solve with its coupling's line.
     */
    LinearSolveReport
    solve_bordered(const double relative_tolerance,
                   const bool   estimate_condition);

    /**
     * @brief Add the linear solve's solution to the displacement increment
     * and the couplings' rows of unknowns.
     */
    void
    add_solution();

    /** Whether assemble_matrix() checks its matrix. */
    bool checks_tangent = false;
    /** The worst of the checks since the last take_tangent_check(). */
    TangentCheckResult tangent_check_result;
  };
} // namespace impm

#endif
