#ifndef impm_simulator_mpm_solver_h
#define impm_simulator_mpm_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <impm/assembly/assembler.h>
#include <impm/core/effects.h>
#include <impm/core/parameters.h>
#include <impm/coupling/couplings.h>
#include <impm/grid/background_grid.h>
#include <impm/io/checkpoint.h>
#include <impm/io/run_state.h>
#include <impm/points/material_points.h>
#include <impm/postprocess/postprocessor.h>
#include <impm/simulator/run.h>
#include <impm/solver/linear_solver.h>
#include <impm/solver/load_step_control.h>
#include <impm/solver/load_step_problem.h>
#include <impm/solver/newton_solver.h>
#include <impm/system/load_step_system.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace impm
{
  using namespace dealii;

  /**
   * @brief The implicit material point solver in the previously converged
   * Lagrangian form (the paper's eq. 9-10) or the updated Lagrangian one.
   *
   * It owns the parts of a run and orchestrates each load step: the basis
   * evaluated once on the start-of-step grid and the compact numbering of
   * the DoFs that points touch (LoadStepSystem), full Newton with the
   * consistent tangent (NewtonSolver on a LoadStepProblem), the step
   * control's verdict (LoadStepControl), the convection of the points
   * (MaterialPoints), the scene's couplings (Couplings: it names none of
   * them) and the postprocessors (PostprocessorManager). See
   * doc/architecture.md.
   *
   * @tparam dim Space dimension.
   */
  template <int dim>
  class MPMSolver
  {
  public:
    /**
     * @brief Set up the grid, the points and the solvers of a scene.
     * @param settings The scene (with its bodies and their materials) and
     *   the modules' parameters (solver, output, testing, checkpoints).
     * @param prm The scene's parameter file (the couplings read their
     *   subsections).
     * @param force_effects The loads the scene enables.
     * @param communicator The processes that share the work.
     * @param resume_state If not null, the state of the checkpoint to
     *   continue from, whose grid and points are in @p checkpoint_grid.
     * @param checkpoint_grid The checkpoint's grid file.
     */
    MPMSolver(const RunParameters<dim>                      &settings,
              ParameterHandler                              &prm,
              std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects,
              const MPI_Comm                                 communicator,
              const RunState    *resume_state    = nullptr,
              const std::string &checkpoint_grid = "");

    /**
     * @brief Run all load steps, writing what the scene's postprocessors
     * write. Throws if a load step cannot be solved.
     */
    void
    run();

    /** @brief The material points (at the last converged step). */
    const MaterialPoints<dim> &
    points() const
    {
      return material_points;
    }

    /** @brief The number of the last converged load step (0: none). */
    unsigned int
    last_converged_step() const
    {
      return converged_step;
    }

    /**
     * @brief A test run() makes after every converged load step, on every
     * process: a non-empty reason stops the run there (the point files end
     * with that step, no summary is written), as a strength reduction's
     * displacement limit does. It must be collective (the same answer on
     * every process).
     */
    void
    set_stop_condition(const std::function<std::string()> &condition)
    {
      stop_condition = condition;
    }

    /** @brief The load factor of the last converged load step. */
    double
    converged_load_factor() const
    {
      return converged_load;
    }

    /** @brief The reason the stop condition gave, or empty. */
    const std::string &
    stopped_by_condition() const
    {
      return stop_reason;
    }

  private:
    /** Create the output directory and start the effects and the
     *  postprocessors; print the start-up report. */
    void
    start_run();

    /** One line per effect, grid face condition and coupling. */
    std::vector<std::string>
    describe_effects() const;

    /** Evaluate the basis and number the system of a new load step. */
    void
    set_up_load_step();

    /** Solve the next load step of @p control once and judge the outcome. */
    StepRecord
    attempt_load_step(const LoadStepControl &control);

    /** Take the converged step of @p record: reactions, point update. */
    void
    accept_load_step(StepRecord &record);

    /** On several processes, repartition the grid by the points' cell
     *  weights when the points are out of balance. */
    void
    balance_load();

    /** Save the run after the converged step @p step_number of
     *  @p control; @p elapsed: this run's wall time so far. */
    void
    write_checkpoint(const LoadStepControl &control,
                     const unsigned int     step_number,
                     const double           elapsed);

    /** The bytes a checkpoint will take on all processes together and
     *  those of its largest file (the points' data), estimated from the
     *  points and cells (collective). */
    Checkpoint::Size
    estimated_checkpoint_size() const;

    /** Whether to stop (and checkpoint) now: the wall-time limit has
     * passed on any process; the reason. */
    std::string
    reason_to_stop(const double elapsed) const;

    /** After a signal (StopSignal) on any process, in the attempt @p
     * record (abandoned, NewtonOutcome::interrupted, or converged): save
     * the last converged state of @p control in a checkpoint unless the
     * newest holds it, and throw a StoppedBySignal. Collective;
     * @p elapsed: this run's wall time so far. */
    [[noreturn]] void
    stop_for_signal(const LoadStepControl &control,
                    const StepRecord      &record,
                    const double           elapsed);

    /** The modules' parameters. */
    const RunParameters<dim> &settings;
    /** The scene's parameter file (postprocessors read their subsections
     *  when the run starts). */
    ParameterHandler &prm;
    /** The scene as kept in each checkpoint (SceneRecord::to_text(), made
     *  at the first checkpoint: the scene does not change in a run). */
    std::string scene_text;
    /** The scene's description (settings.scene). */
    const Parameters::All<dim>                          &parameters;
    const std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects;
    const MPI_Comm                                       communicator;
    /** Progress (rank 0, not in test mode, not with Output/Quiet). */
    ConditionalOStream pcout;
    /** Messages that test mode prints too (rank 0). */
    ConditionalOStream root_out;
    TimerOutput        timer;

    BackgroundGrid<dim> grid;
    /** The map from the steps' progress to time and load factor. */
    LoadPath load_path;
    /** The couplings the scene asks for. */
    Couplings<dim>                             couplings;
    MaterialPoints<dim>                        material_points;
    LoadStepSystem<dim>                        system;
    std::unique_ptr<Assembler<dim>>            assembler;
    std::unique_ptr<LinearSolver>              linear_solver;
    LoadStepProblem<dim>                       problem;
    NewtonSolver                               newton_solver;
    std::vector<std::string>                   effect_descriptions;
    std::unique_ptr<PostprocessorManager<dim>> postprocessors;
    /** The checkpoint's state in a resumed run, else null. */
    const RunState *resume_state;
    /** The number of the last converged load step. */
    unsigned int converged_step = 0;
    /** The load step of the newest checkpoint (of this run or the one it
     *  resumed; 0: none). */
    unsigned int checkpointed_step = 0;
    /** The load factor of the last converged load step. */
    double converged_load = 0.;
    /** See set_stop_condition(). */
    std::function<std::string()> stop_condition;
    /** What stop_condition said when it stopped the run. */
    std::string stop_reason;
  };
} // namespace impm

#endif
