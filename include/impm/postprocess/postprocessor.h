#ifndef impm_postprocess_postprocessor_h
#define impm_postprocess_postprocessor_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <impm/base/plugin_list.h>
#include <impm/core/parameters.h>
#include <impm/coupling/couplings.h>
#include <impm/grid/background_grid.h>
#include <impm/io/run_state.h>
#include <impm/points/material_points.h>
#include <impm/postprocess/output_parameters.h>
#include <impm/solver/newton_solver.h>
#include <impm/solver/solver_parameters.h>

#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace impm
{
  using namespace dealii;

  /** @brief The solver's timed phases (TimerOutput sections), in order. */
  inline const std::vector<std::string> solver_phases = {"basis evaluation",
                                                         "system setup",
                                                         "stress update",
                                                         "assembly",
                                                         "linear solve",
                                                         "point update",
                                                         "load balance",
                                                         "output"};

  /**
   * @brief What postprocessors may read of a run: the scene and the parts
   * of the solver, fixed for the run.
   */
  template <int dim>
  struct RunContext
  {
    /** The scene's description. */
    const Parameters::All<dim> &parameters;
    /** The solver's parameters. */
    const Parameters::Solver &solver;
    /** What is written, and how often. */
    const Parameters::Output &output;
    /** The test summary's settings. */
    const Parameters::Testing &testing;
    /** The scene's time (subsection `Time`). */
    const Parameters::Time &time;
    /** The background grid (DoFs, face conditions). */
    const BackgroundGrid<dim> &grid;
    /** The material points in their current state. */
    const MaterialPoints<dim> &material_points;
    /** One line per effect of the scene (loads, faces, stabilisation). */
    const std::vector<std::string> &effect_descriptions;
    /** Whether the scene has force effects (loads). */
    const bool has_force_effects;
    /** The solver's phase timer. */
    TimerOutput &timer;
    /** The processes of the run. */
    const MPI_Comm communicator;
    /** The scene's couplings (Couplings::find() finds one by type). */
    const Couplings<dim> &couplings;
    /** The scene's parameter file: a postprocessor registered with a
     *  declaration (IMPM_REGISTER_POSTPROCESSOR_WITH_PARAMETERS) reads its
     *  own subsection, which is entered while it is created. */
    ParameterHandler &prm;
    /** The columns of StepMeasure values (set by the PostprocessorManager
     *  from all postprocessors' step_measure_columns()). */
    std::vector<std::string> step_measure_columns = {};
  };

  /**
   * @brief The scales in which the test summary prints the step measures:
   * the reference length L and the reference force S L^(dim-1) of
   * Parameters::Testing.
   */
  struct MeasureScales
  {
    /** Lengths are printed divided by this (m). */
    double length;
    /** Forces are printed divided by this (N, per m in 2D). */
    double force;
    /** Energies are printed divided by this (J, per m in 2D). */
    double energy;
  };

  /** @brief One attempt at a load step. */
  struct StepRecord
  {
    /** Number of the load step (converged steps before it + 1). */
    unsigned int step_number = 0;
    /** The load factor at the start of the attempt. */
    double start = 0.;
    /** The load factor at the target of the attempt. */
    double target = 0.;
    /** The run's progress (0 at its start, 1 at its end: the load factor
     *  of a quasi-static scene, the time over the end time of one in time)
     *  at the start of the attempt. */
    double start_progress = 0.;
    /** The run's progress at the target of the attempt. */
    double target_progress = 0.;
    /** The time at the step's end in s (-1 in a scene without time). */
    double end_time = -1.;
    /** Whether the step ends the run (its target is the end). */
    bool last = false;
    /** The Newton solve, with the outcome the step control judged. */
    NewtonRecord newton;
    /** DoFs of the step's linear system. */
    types::global_dof_index system_dofs = 0;
    /** Largest point displacement of the solve, in cells. */
    double point_increment = 0.;
    /** Converged steps only: reactions per
     *  BackgroundGrid::reaction_columns(). */
    std::vector<double> reactions;
    /** Converged steps only: the reactions' imbalance (negative if not
     *  measured). */
    double reaction_imbalance = -1.;
    /** Values measured by postprocessors (converged steps only). */
    std::vector<StepMeasure> measures;
    /** Testing/Check tangent only: the largest relative difference between
     *  an assembled matrix of the attempt and its central differences
     *  (negative: not checked). */
    double tangent_difference = -1.;
    /** Testing/Check tangent only: the columns left out because their
     *  perturbation changed a contact's state. */
    unsigned int tangent_columns_across_kinks = 0;

    /** @brief Whether the attempt converged and was accepted. */
    bool
    converged() const
    {
      return newton.outcome == NewtonOutcome::converged;
    }

    /**
     * @brief The line of the progress log (without the residual):
     * "step   3  load 0.0750  iterations 4  error 1.2e-03" or
     * "step   3  load 0.0750  diverged after 5 iterations: step cut";
     * the measures in SI units, to 5 significant digits.
     */
    std::string
    log_line() const;

    /**
     * @brief The line of the test summary: as log_line(), but with the
     * forces and lengths among the measures divided by @p scales and
     * printed to 6 decimals, and counts as integers (see MeasureKind), so
     * that a test compares them to 1e-6 of its scales as the rest of the
     * summary: "step   3  load 0.0750  iterations 4  R1x 0.018258  R1c 32".
     */
    std::string
    log_line(const MeasureScales &scales) const;
  };

  // The nodal state of a converged step (solver/load_step_problem.h).
  template <int dim>
  struct ConvergedStep;

  /** @brief Totals over the run's load steps, for the summaries. */
  template <int dim>
  struct RunStatistics
  {
    /** Converged load steps. */
    unsigned int n_converged_steps = 0;
    /** Attempts that were cut. */
    unsigned int n_cuts = 0;
    /** Newton iterations of all attempts. */
    unsigned int total_newton_iterations = 0;
    /** Residual evaluations (stress updates). */
    unsigned int residual_evaluations = 0;
    /** The line search's residual evaluations among them. */
    unsigned int line_search_evaluations = 0;
    /** System DoFs of the last attempt. */
    types::global_dof_index system_dofs_last_step = 0;
    /** Largest point displacement of an accepted step, in cells. */
    double largest_point_increment = 0.;
    /** Largest |sum of reactions + external force| / |external force|. */
    double max_reaction_imbalance = 0.;
    /** Worst condition estimate (0 if none was made). */
    double worst_condition = 0.;
    /** Smallest observed Newton order of the converged steps (see
     *  NewtonRecord::observed_order()). */
    double min_newton_order = NewtonRecord().observed_order();
    /** The largest StepRecord::tangent_difference (negative: not
     *  checked). */
    double max_tangent_difference = -1.;
    /** The sum of StepRecord::tangent_columns_across_kinks. */
    unsigned int tangent_columns_across_kinks = 0;
    /** Reactions of the last converged step. */
    std::vector<double> last_reactions;
    /** Measures of the last converged step. */
    std::vector<StepMeasure> last_measures;
    /** Set at the end of the run: the wall time (s). */
    double wall_time = 0.;
    /** Set at the end of the run: the points' state. */
    PointMeasures<dim> final_state;

    /** @brief Count the attempt @p record in. */
    void
    add(const StepRecord &record);

    /** @brief Save the statistics of the steps so far. */
    void
    save(RunState &state) const;

    /** @brief Continue from the statistics saved by save(). */
    void
    load(const RunState &state);
  };

  /**
   * @brief A postprocessor: writes or measures something of a run. The
   * solver calls every postprocessor the scene asks for; it does not know
   * what they write.
   *
   * Postprocessors run in the order of their names. All measure_step()
   * calls of a step come before all after_step() calls.
   *
   * To add one: derive from this class in a file of source/postprocess/ and
   * register it with IMPM_REGISTER_POSTPROCESSOR; its create function
   * returns nullptr when the scene does not ask for it.
   */
  template <int dim>
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** @brief Columns of the StepMeasure values this one adds. */
    virtual std::vector<std::string>
    step_measure_columns() const
    {
      return {};
    }

    /** @brief Called once before the first load step. */
    virtual void
    start(const RunContext<dim> &context);

    /**
     * @brief Instead of start(), in a run resumed from a checkpoint: take
     * up the files and records from @p state (saved by save()).
     */
    virtual void
    resume(const RunContext<dim> &context, const RunState &state);

    /**
     * @brief Save what resume() needs (the records behind the files) into
     * @p state, when a checkpoint is written.
     */
    virtual void
    save(const RunContext<dim> &context, RunState &state) const;

    /** @brief Add measures to a converged step's @p record. */
    virtual void
    measure_step(const RunContext<dim> &context, StepRecord &record);

    /**
     * @brief Called for a converged step @p record before the points move
     * (the step's grid and nodal vectors in @p step; nothing else is made
     * for it), before measure_step() and after_step().
     */
    virtual void
    after_convergence(const RunContext<dim>    &context,
                      const StepRecord         &record,
                      const ConvergedStep<dim> &step);

    /** @brief Called after every attempt, converged or cut. */
    virtual void
    after_step(const RunContext<dim>    &context,
               const StepRecord         &record,
               const RunStatistics<dim> &statistics);

    /** @brief Called once after the full load is reached. */
    virtual void
    finish(const RunContext<dim>    &context,
           const RunStatistics<dim> &statistics);

    /**
     * @brief Called once when the run stops on a load step it cannot
     * solve (LoadStepFailure), with the points at the last converged
     * step, whose load factor is @p converged_load_factor: the point files
     * then end with the state the failure started from.
     */
    virtual void
    after_failure(const RunContext<dim> &context,
                  const double           converged_load_factor);
  };

  /** @brief The registry of postprocessors (see PluginList). */
  template <int dim>
  using PostprocessorList =
    PluginList<Postprocessor<dim>, const RunContext<dim> &>;

  /**
   * @brief The postprocessors of a run, with its statistics: created from
   * the registry, called in turn.
   */
  template <int dim>
  class PostprocessorManager
  {
  public:
    /** @brief Create every postprocessor the scene of @p context asks for. */
    explicit PostprocessorManager(const RunContext<dim> &context);

    /**
     * @brief Declare the subsection of every postprocessor registered with
     * parameters, named after it.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /** @brief See Postprocessor::start(). */
    void
    start();

    /** @brief Start every postprocessor of a resumed run from @p state, and
     *  the run's statistics. */
    void
    resume(const RunState &state);

    /** @brief Save the postprocessors' records and the statistics, with
     *  @p elapsed_wall_time of this run added to the wall time. */
    void
    save(RunState &state, const double elapsed_wall_time) const;

    /** @brief See Postprocessor::after_convergence(). */
    void
    after_convergence(const StepRecord &record, const ConvergedStep<dim> &step);

    /** @brief Measure, count and write the attempt @p record. */
    void
    after_step(StepRecord &record);

    /** @brief Measure the final state and write the run's summaries. */
    void
    finish(const double wall_time);

    /** @brief See Postprocessor::after_failure(). */
    void
    after_failure(const double converged_load_factor);

  private:
    RunContext<dim>                                  context;
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors;
    RunStatistics<dim>                               statistics;
  };
} // namespace impm

/**
 * Register @p CLASS (a template over dim, constructed from a RunContext or
 * by default) as postprocessor @p NAME, created when @p WANTED (an
 * expression of `const RunContext<dim> &context`) holds.
 */
#define IMPM_REGISTER_POSTPROCESSOR(CLASS, NAME, WANTED) \
  IMPM_REGISTER_POSTPROCESSOR_WITH_PARAMETERS(CLASS, NAME, WANTED, {})

/**
 * As IMPM_REGISTER_POSTPROCESSOR, with @p DECLARE (a function of
 * `ParameterHandler &`) declaring the entries of its own subsection @p NAME;
 * that subsection is entered while @p WANTED is evaluated and @p CLASS is
 * constructed, so both read it through `context.prm`.
 */
#define IMPM_REGISTER_POSTPROCESSOR_WITH_PARAMETERS(CLASS,                  \
                                                    NAME,                   \
                                                    WANTED,                 \
                                                    DECLARE)                \
  IMPM_REGISTER_PLUGIN_IN_BOTH_DIMENSIONS(                                  \
    impm::PostprocessorList,                                                \
    CLASS,                                                                  \
    NAME,                                                                   \
    DECLARE,                                                                \
    ([](const impm::RunContext<dim> &context)                               \
       -> std::unique_ptr<impm::Postprocessor<dim>> {                       \
      if (!(WANTED))                                                        \
        return nullptr;                                                     \
      if constexpr (std::is_constructible_v<CLASS<dim>,                     \
                                            const impm::RunContext<dim> &>) \
        return std::make_unique<CLASS<dim>>(context);                       \
      else                                                                  \
        return std::make_unique<CLASS<dim>>();                              \
    }))

#endif
