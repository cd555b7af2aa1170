#ifndef impm_solver_newton_solver_h
#define impm_solver_newton_solver_h

#include <impm/core/parameters.h>
#include <impm/solver/linear_solver.h>
#include <impm/solver/solver_parameters.h>

#include <array>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace impm
{
  /** @brief Why a Newton solve stopped. */
  enum class NewtonOutcome
  {
    /** The relative residual fell below 'Solver/Tolerance'. */
    converged,
    /** 'Solver/Maximum iterations' were spent. */
    iteration_limit,
    /** The residual grew past 'Solver/Divergence factor' times the first. */
    diverged,
    /** The residual is not a finite number. */
    not_finite,
    /** A point's deformation increment has J <= 0. */
    inverted_point,
    /** A linear solve failed (see NewtonRecord::linear_solves). */
    linear_solve_failed,
    /** Converged, but a point moved more than 'Solver/Maximum point
     *  increment' cells (set by the load-step control, not by Newton). */
    increment_too_large,
    /** An explicit time step above the stable one (no Newton solve). */
    above_stable_step,
    /** Converged, but a coupling refused the step (Coupling::refuse_step(),
     *  the reason in NewtonRecord::refusal; set by MPMSolver). */
    step_refused,
    /** Abandoned at a signal (NewtonSolver::set_interruption()). */
    interrupted
  };

  /** @brief The words for each NewtonOutcome, as the log and errors print. */
  constexpr std::array<const char *, 10> newton_outcome_names = {
    {"converged",
     "iteration limit",
     "diverged",
     "non-finite residual",
     "inverted point",
     "linear solve failed",
     "point increment too large",
     "time step above the stable one",
     "step refused",
     "interrupted"}};

  /** @brief The name of @p outcome. */
  inline std::string
  name_of(const NewtonOutcome outcome)
  {
    return newton_outcome_names[static_cast<unsigned int>(outcome)];
  }

  /**
   * @brief The nonlinear problem a NewtonSolver solves: the residual of the
   * current iterate, the matrix, and the update by a linear solve.
   */
  class NonlinearProblem
  {
  public:
    virtual ~NonlinearProblem() = default;

    /** @brief The residual of the current iterate. */
    struct Residual
    {
      /** False if the iterate is inadmissible (an inverted point). */
      bool admissible = true;
      /** The residual norm relative to the problem's force scale. */
      double relative = 0.;
      /** The residual norm (N). */
      double norm = 0.;
      /** The norm of the internal forces it is the difference to (N): the
       *  scale of its round-off. */
      double internal_force_norm = 0.;
      /** Whether a contact changed its state (into or out of contact,
       *  stick or slip) since the previous iterate: the residual is not
       *  smooth between the two, and their contraction is not Newton's. */
      bool contact_changed = false;
      /** The size of the round-off in the forces (N, Coupling::
       *  round_off_force()): a norm at or below it is converged. */
      double round_off = 0.;
    };

    /** @brief Evaluate the residual of the current iterate. */
    virtual Residual
    evaluate_residual() = 0;

    /** @brief Assemble the tangent matrix of the current iterate. */
    virtual void
    assemble_matrix() = 0;

    /**
     * @brief Solve with the last matrix and residual and, if the solve
     * succeeded, add the correction to the iterate.
     * @param relative_tolerance The factor an iterative linear solver must
     * reduce the residual by (the forcing term).
     * @param estimate_condition Also estimate the matrix's condition number.
     */
    virtual LinearSolveReport
    solve_and_update(const double relative_tolerance,
                     const bool   estimate_condition) = 0;

    /**
     * @brief Add @p factor times the last correction of solve_and_update()
     * to the iterate (a line search's step back along it: a negative
     * factor).
     */
    virtual void
    move_along_last_correction(const double factor) = 0;
  };

  /** @brief What one Newton solve did. */
  struct NewtonRecord
  {
    /** Why it stopped. */
    NewtonOutcome outcome = NewtonOutcome::converged;
    /** Relative residual of each iterate, the start included. */
    std::vector<double> residuals;
    /** For each iterate, whether a contact changed state since the one
     *  before (Residual::contact_changed). */
    std::vector<bool> contact_changed;
    /** The last iterate's residual norm. */
    double last_norm = 0.;
    /** The last iterate's internal force norm (N). */
    double last_internal_force_norm = 0.;
    /** The linear solve of each iteration (the last may have failed). */
    std::vector<LinearSolveReport> linear_solves;
    /** For each linear solve, whether it was an iterative solve whose
     *  forcing term came from the Newton tolerance rather than from the
     *  residual (NewtonSolver::linear_tolerance): it was asked only to bring
     *  the residual below the tolerance, not to contract quadratically. */
    std::vector<bool> asked_for_tolerance_only;
    /** NewtonOutcome::step_refused: the reason (StepRefusal). */
    std::string refusal;
    /** Whether a smaller step may pass (false: the run stops). */
    bool smaller_step_may_pass = true;
    /** Whether the step was explicit: no Newton solve, no residual (its
     *  outcome is that of the explicit update). */
    bool explicit_step = false;
    /** An explicit step: the largest time step (s) its start allows at
     *  the Courant number (infinite if none is known). */
    double largest_time_step = std::numeric_limits<double>::infinity();
    /** The residual evaluations of the line search ('Solver/Line
     *  search') beyond one per iterate: one per halving of a correction,
     *  and one to return to the best step tried. */
    unsigned int line_search_evaluations = 0;

    /** @brief The outcome's name, with the cause of a failed linear solve
     *  or the reason of a refused step. */
    std::string
    outcome_description() const;

    /** @brief Newton iterations made (linear solves). */
    unsigned int
    n_iterations() const
    {
      return residuals.empty() ? 0 : residuals.size() - 1;
    }

    /** @brief The last relative residual (NaN if none was evaluated). */
    double
    final_residual() const
    {
      return residuals.empty() ? std::numeric_limits<double>::quiet_NaN() :
                                 residuals.back();
    }

    /**
     * @brief The smallest observed order log r_{k+1} / log r_k over the
     * contractions near the solution (r_k < 1e-3) and above round-off
     * (r_{k+1} > 1e-10): about 2 for full Newton. Pairs between which a
     * contact changed state are not counted (semi-smooth Newton is
     * quadratic once the contact states are settled), nor pairs joined by
     * an iterative linear solve that was asked only to reach the Newton
     * tolerance (asked_for_tolerance_only: an inexact Newton step whose
     * contraction is the forcing term's, not Newton's). Returns the largest
     * double if no pair qualifies (see is_measured()).
     */
    double
    observed_order() const;

    /** @brief Whether observed_order() had a residual pair to measure. */
    static bool
    is_measured(const double order);
  };

  /**
   * @brief Full Newton iteration with the checks of 'Solver': stops when the
   * relative residual falls below the tolerance, grows past the divergence
   * factor, is not finite, the iterate is inadmissible, or the iterations
   * run out.
   */
  class NewtonSolver
  {
  public:
    /** @brief A solver with the scene's tolerances and limits. */
    explicit NewtonSolver(const Parameters::Solver &parameters);

    /** @brief Iterate on @p problem from its current iterate. */
    NewtonRecord
    solve(NonlinearProblem &problem) const;

    /**
     * @brief Check @p interrupted before every iteration (a collective
     * check, the same on every process): when it returns true the solve
     * stops with NewtonOutcome::interrupted.
     */
    void
    set_interruption(std::function<bool()> interrupted);

    /**
     * @brief The relative tolerance of the linear solve after a relative
     * residual @p residual: 'Solver/Linear tolerance', or with 'Solver/
     * Adaptive linear tolerance' the forcing term min(eta_max, max(0.1 r,
     * tol / (2 r))) bounded below by it, eta_max 'Solver/Largest linear
     * tolerance': loose far from the solution, tight near it so that Newton
     * stays quadratic (Eisenstat and Walker's choice 2 with gamma = 0.1,
     * alpha = 2, on the relative residual), and never tighter than needed
     * to bring the residual below the Newton tolerance. The cap eta_max
     * (default 1e-2) is tighter than theirs: with 0.1, the Mohr-Coulomb
     * footing at h = 0.0625 m wandered for whole load steps where points
     * change return region (11,025 Newton iterations and 1,363 load steps
     * against 467 and 50; doc/benchmarks/parallel_and_solvers.md, "The
     * forcing term's cap").
     * After an iterate in which a contact changed its state (@p
     * contact_changed), 'Solver/Linear tolerance' itself: an inexact
     * correction across a contact's kink let Newton cycle between contact
     * states on a stiff penalty (the plate at h = 1/32 m with penalty
     * factor 1000; doc/benchmarks/contact.md, "Contact with the iterative
     * solver").
     */
    double
    linear_tolerance(const double residual,
                     const bool   contact_changed = false) const;

  private:
    /**
     * @brief 'Solver/Line search': the iterate the last correction reached
     * has the residual @p full; if it is inadmissible, not finite or has
     * not fallen by the fraction 1e-4 of the step (Armijo's condition on
     * the relative residual, against @p record's last accepted one), halve
     * the step along the correction, up to 5 times, until one has; if none
     * has, keep the step of the smallest admissible residual tried (if
     * none was admissible, the last tried: the solve fails as with the full
     * step). A full step across which a contact changed state is kept
     * whole. Returns the kept iterate's residual; counts its residual
     * evaluations in @p record.
     */
    NonlinearProblem::Residual
    search_along_correction(NonlinearProblem                 &problem,
                            const NonlinearProblem::Residual &full,
                            NewtonRecord                     &record) const;

    /** @brief Whether @p residual meets the tolerances (converged). */
    bool
    meets_tolerance(const NonlinearProblem::Residual &residual) const;

    const Parameters::Solver &parameters;
    /** set_interruption()'s check (empty: none). */
    std::function<bool()> interrupted;
  };
} // namespace impm

#endif
