#ifndef impm_solver_load_step_control_h
#define impm_solver_load_step_control_h

#include <impm/core/parameters.h>
#include <impm/io/run_state.h>
#include <impm/solver/newton_solver.h>
#include <impm/solver/solver_parameters.h>

#include <limits>
#include <sstream>

namespace impm
{
  /**
   * @brief The load-step control: which load step to try next, and what to
   * do with the outcome of a Newton solve.
   *
   * The load factor goes from 0 to 1 in 'Solver/Load steps' nominal steps.
   * Given an outcome, the control advances (and after an easy step, with
   * at most 'Solver/Easy iterations' iterations, doubles the step back
   * towards the nominal one, but not to an increment a coupling refused),
   * repeats the step with half the increment
   * ('Solver/Step control'), or stops the run with a message naming the
   * load step and every failed attempt. The last step lands exactly on the
   * full load. In a scene in time the progress from 0 to 1 is the share
   * of 'Time/End time' reached, and the messages give times in seconds.
   */
  class LoadStepControl
  {
  public:
    /** @brief The control of the scene's 'Solver' section; @p end_time is
     *  the scene's end time in s (0: a scene without time, whose progress
     *  is the load factor). */
    explicit LoadStepControl(const Parameters::Solver &parameters,
                             double                    end_time = 0.);

    /** @brief Whether the full load has been reached. */
    bool
    finished() const
    {
      return load_factor >= 1.;
    }

    /** @brief The load factor at the start of the next attempt. */
    double
    start() const
    {
      return load_factor;
    }

    /** @brief The load factor the next attempt aims for. */
    double
    target() const;

    /** @brief The number of the next load step (converged steps + 1). */
    unsigned int
    step_number() const
    {
      return n_converged + 1;
    }

    /**
     * @brief The outcome of a Newton solve as the control judges it: a
     * converged solve that moved a point by more than 'Solver/Maximum point
     * increment' cells (@p point_increment) is cut too, when step control
     * is on, since the basis of the step is that of its start.
     */
    NewtonOutcome
    judge(const NewtonOutcome outcome, const double point_increment) const;

    /**
     * @brief Advance or cut after an attempt with @p record (whose outcome
     * is the judged one, or NewtonOutcome::step_refused: cut, or stop at
     * once when no smaller step may pass). A failure halves the step (no
     * further than explicit_limit()); an explicit step above its start's
     * stable step (NewtonOutcome::above_stable_step) goes straight to
     * explicit_limit(). Throws a LoadStepFailure with the message for the
     * user when the run cannot go on.
     */
    void
    update(const NewtonRecord &record);

    /** @brief Save the control's state (load factor, step size, steps). */
    void
    save(RunState &state) const;

    /** @brief Continue from a state saved by save(). */
    void
    load(const RunState &state);

    /** The iterations over which a stalled residual is judged. */
    static constexpr unsigned int stall_length = 5;

    /**
     * @brief Whether the last stall_length relative @p residuals of a
     * Newton solve lie within 25 % of each other below 1e-3: a floor the
     * iterations do not lower (the failure's message then suggests
     * 'Solver/Absolute tolerance'), not a cycle between states.
     */
    static bool
    stalled(const std::vector<double> &residuals);

  private:
    /** @brief A progress and an increment of it as the messages give them:
     *  "load 0.5 (increment 0.1)" or "t 0.5 s (step 0.1 s)". */
    std::string
    describe_attempt(double progress, double increment) const;

    /** @brief The smallest increment a cut may reach: 'Solver/Minimum load
     *  step', or where the nominal step is not above it (an explicit run of
     *  more steps than its inverse), 1/1024 of the nominal step, so that a
     *  step can still be cut (ten halvings). */
    double
    smallest_step() const;

    /** @brief An explicit step's largest increment from its start at the
     *  Courant number (NewtonRecord::largest_time_step over the end time),
     *  which a cut goes to and growth stops at; infinite otherwise. */
    double
    explicit_limit(const NewtonRecord &record) const;

    const Parameters::Solver &parameters;
    /** The scene's end time in s (0: none). */
    const double end_time;
    const double nominal_step;
    double       step_size;
    double       load_factor = 0.;
    unsigned int n_converged = 0;
    /** The smallest increment a coupling refused in this run
     *  (NewtonOutcome::step_refused): an easy step does not grow the next
     *  to it (not kept in a checkpoint: a resumed run may try it once
     *  more). */
    double refused_increment = std::numeric_limits<double>::infinity();
    /** Steps converged in a row at the current increment. */
    unsigned int n_steady = 0;
    /** The steady steps a growth needs ('Solver/Steady steps before
     *  growth', doubled by each grown step that failed). */
    unsigned int n_steady_needed;
    /** Whether the current increment was grown by a steady run and no step
     *  has converged at it yet. */
    bool untried_steady_growth = false;
    /** Each failed attempt of the run, for the final error message. */
    std::ostringstream failures;
  };
} // namespace impm

#endif
