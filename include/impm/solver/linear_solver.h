#ifndef impm_solver_linear_solver_h
#define impm_solver_linear_solver_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <impm/core/parameters.h>
#include <impm/solver/solver_parameters.h>
#include <impm/system/near_null_space.h>

#include <memory>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /** @brief What one linear solve did. */
  struct LinearSolveReport
  {
    /** Whether the solve succeeded. */
    bool success = true;
    /** Krylov iterations (0 for a direct solver). */
    unsigned int iterations = 0;
    /** Wall time of the solve, in seconds. */
    double seconds = 0.;
    /** The condition estimate, if asked for and available (else 0). */
    double condition_estimate = 0.;
    /** If it failed: one line naming the solver and the cause. */
    std::string failure;
  };

  /** @brief One linear system to solve, and how. */
  struct LinearSolveRequest
  {
    /** The matrix. */
    const TrilinosWrappers::SparseMatrix &matrix;
    /** The solution (overwritten). */
    TrilinosWrappers::MPI::Vector &solution;
    /** The right-hand side. */
    const TrilinosWrappers::MPI::Vector &rhs;
    /** An iterative solver stops when the residual has fallen by this
     *  factor (a direct solver ignores it). */
    double relative_tolerance;
    /** Also estimate the matrix's condition number, where the solver can. */
    bool estimate_condition;
    /** More right-hand sides with the same matrix, solved into @p
     *  additional_solutions (as many, of the same partition) with the
     *  factorisation or preconditioner of the first: the bordered systems
     *  of rigid bodies pushed by a force. An iterative solver solves them to
     *  'Solver/Linear tolerance', not to @p relative_tolerance: their
     *  solutions enter a Schur complement, the difference of a body's
     *  contact stiffness and what the material passes on, which cancels
     *  (with a forcing term of 1e-2, contact_plate_force_driven cycled at
     *  a relative residual of 1e-8). */
    std::vector<const TrilinosWrappers::MPI::Vector *>
      additional_right_hand_sides = {};
    /** Where the additional right-hand sides' solutions go. */
    std::vector<TrilinosWrappers::MPI::Vector *> additional_solutions = {};
  };

  /**
   * @brief The linear solver of the Newton iterations, chosen once from the
   * scene's 'Solver/Linear solver'.
   *
   * A solve that fails (no convergence, a failed factorisation) is reported,
   * never thrown: the Newton solve then fails, and the load-step control
   * cuts the step or stops the run with the report's line.
   *
   * To add a solver: a value of Parameters::LinearSolverType with its name in
   * Parameters::linear_solver_names, a class derived from this one in
   * linear_solver.cc, and its case in create().
   */
  class LinearSolver
  {
  public:
    /**
     * @brief The solver the scene names.
     * @param parameters The scene's solver parameters (type, tolerance).
     * The processes are those of the system's vectors.
     */
    static std::unique_ptr<LinearSolver>
    create(const Parameters::Solver &parameters);

    virtual ~LinearSolver() = default;

    /**
     * @brief Whether the solver uses the near null space of the system
     * (see set_near_null_space()).
     */
    virtual bool
    needs_near_null_space() const
    {
      return false;
    }

    /**
     * @brief The rigid-body modes of the current system
     * (LoadStepSystem::rigid_body_modes()). Called after every setup of
     * the system that makes a new matrix (a setup that keeps the matrix
     * of the step before keeps its rows and modes): a solver that keeps
     * something made from the last matrix (GMRES with AMG: its hierarchy)
     * drops it here.
     */
    virtual void
    set_near_null_space(NearNullSpace modes)
    {
      (void)modes;
    }

    /**
     * @brief One line on how the solver worked over the run (for the
     * run's last lines), or nothing.
     */
    virtual std::string
    statistics() const
    {
      return "";
    }

    /** @brief Solve the system of @p request. */
    LinearSolveReport
    solve(const LinearSolveRequest &request);

  protected:
    /**
     * @brief The solve itself: fills @p report, and throws (anything) on
     * failure; solve() turns that into a failed report.
     */
    virtual void
    try_solve(const LinearSolveRequest &request, LinearSolveReport &report) = 0;

    /** @brief The solver's name in the scene, for failure reports. */
    virtual std::string
    name() const = 0;
  };
} // namespace impm

#endif
