#include <deal.II/base/utilities.h>

#include <impm/base/errors.h>
#include <impm/base/stop_signal.h>
#include <impm/core/scene_checks.h>
#include <impm/io/checkpoint.h>
#include <impm/io/output_directory.h>
#include <impm/io/scene_record.h>
#include <impm/simulator/mpm_solver.h>
#include <impm/simulator/run.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace impm
{
  namespace
  {
    /** The sum of the effects' accelerations acting from the first step. */
    template <int dim>
    Tensor<1, dim>
    acceleration_from_the_start(
      const std::vector<std::unique_ptr<ForceEffect<dim>>> &effects)
    {
      Tensor<1, dim> sum;
      for (const auto &effect : effects)
        sum += effect->acceleration_from_the_start();
      return sum;
    }

    /**
     * The size of a process's per-point step data above which it is
     * returned to the system between load steps (MPMSolver::accept_load_step).
     */
    constexpr std::size_t large_step_data = std::size_t(100) << 20;

    /**
     * The solver parameters the linear solver is made with: 'automatic'
     * solves with KLU when a coupling needs a direct solver
     * (Coupling::needs_direct_solver()).
     */
    template <int dim>
    Parameters::Solver
    linear_solver_parameters(const Parameters::Solver &parameters,
                             const Couplings<dim>     &couplings)
    {
      Parameters::Solver solver = parameters;
      if (couplings.need_direct_solver() &&
          solver.linear_solver == Parameters::LinearSolverType::automatic)
        solver.linear_solver = Parameters::LinearSolverType::direct;
      return solver;
    }

    /** Give the memory the allocator holds free back to the system. */
    void
    return_free_memory()
    {
#ifdef __GLIBC__
      malloc_trim(0);
#endif
    }
  } // namespace



  template <int dim>
  MPMSolver<dim>::MPMSolver(
    const RunParameters<dim>                      &settings,
    ParameterHandler                              &prm,
    std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects,
    const MPI_Comm                                 communicator,
    const RunState                                *resume_state,
    const std::string                             &checkpoint_grid)
    : settings(settings)
    , prm(prm)
    , parameters(settings.scene)
    , force_effects(std::move(force_effects))
    , communicator(communicator)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(communicator) == 0 &&
              !settings.testing.enabled && !settings.output.quiet)
    , root_out(std::cout, Utilities::MPI::this_mpi_process(communicator) == 0)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , grid(parameters.grid, communicator, checkpoint_grid)
    , load_path(settings.time)
    , couplings(
        CouplingInputs<dim>{parameters,
                            prm,
                            grid,
                            settings.time,
                            acceleration_from_the_start(this->force_effects)})
    , material_points(parameters.bodies,
                      grid,
                      communicator,
                      acceleration_from_the_start(this->force_effects),
                      resume_state,
                      couplings.point_fields())
    , system(grid, communicator)
    , assembler(Assembler<dim>::create(settings.solver.formulation,
                                       material_points,
                                       system,
                                       this->force_effects,
                                       couplings.volume_coupling(),
                                       communicator))
    , linear_solver(LinearSolver::create(
        linear_solver_parameters(settings.solver, couplings)))
    , problem(grid, system, *assembler, couplings, *linear_solver, timer)
    , newton_solver(settings.solver)
    , resume_state(resume_state)
  {
    SceneChecks::check_supports(parameters, [this](const unsigned int c) {
      for (const auto &coupling : couplings.list())
        if (coupling->holds_material(c))
          return true;
      return false;
    });
    problem.check_tangents(settings.testing.check_tangent);
    if (couplings.keep_energy_balance())
      problem.keep_energy_balance();
    // A signal abandons the load step in progress at its next Newton
    // iteration, on every process together (MPMSolver::stop_for_signal()).
    newton_solver.set_interruption([this]() {
      return Utilities::MPI::max(StopSignal::received(), this->communicator) !=
             0;
    });
    if (resume_state != nullptr)
      checkpointed_step = static_cast<unsigned int>(
        resume_state->get_double("control.converged steps"));
    for (const auto &coupling : couplings.list())
      if (resume_state == nullptr)
        {
          coupling->check_start(material_points);
          coupling->initialize_points(material_points);
        }
      else
        coupling->load(*resume_state);
    if (Utilities::MPI::n_mpi_processes(communicator) > 1)
      grid.connect_cell_weight(
        [this](const typename Triangulation<dim>::cell_iterator &cell,
               const typename Triangulation<dim>::CellStatus     status) {
          return material_points.cell_weight(cell, status);
        });
  }



  template <int dim>
  void
  MPMSolver<dim>::run()
  {
    Timer wall_timer(communicator);
    wall_timer.start();
    start_run();

    LoadStepControl control(settings.solver, settings.time.end_time);
    if (resume_state)
      control.load(*resume_state);
    bool new_state = true;
    while (!control.finished())
      {
        if (new_state)
          set_up_load_step();
        StepRecord record = attempt_load_step(control);
        if (record.newton.outcome == NewtonOutcome::interrupted)
          stop_for_signal(control, record, wall_timer.wall_time());
        new_state = record.converged();
        if (record.converged())
          {
            accept_load_step(record);
            balance_load();
            converged_step = record.step_number;
            converged_load = record.target;
          }
        // A refusal that stops the run is its error line alone.
        if (record.newton.smaller_step_may_pass)
          postprocessors->after_step(record);
        try
          {
            control.update(record.newton);
          }
        catch (const LoadStepFailure &failure)
          {
            postprocessors->after_failure(failure.converged_load_factor);
            throw;
          }
        if (!record.converged())
          continue;
        if (const std::string failure = couplings.run_failure();
            !failure.empty())
          {
            postprocessors->after_failure(record.target);
            throw CollectiveError(failure);
          }
        if (stop_condition)
          {
            stop_reason = stop_condition();
            if (!stop_reason.empty())
              {
                root_out << "Stopped after load step " << record.step_number
                         << " (" << stop_reason << ")." << std::endl;
                postprocessors->after_failure(control.start());
                return;
              }
          }
        if (Utilities::MPI::max(StopSignal::received(), communicator) != 0)
          stop_for_signal(control, record, wall_timer.wall_time());
        const std::string stop = reason_to_stop(wall_timer.wall_time());
        if (!stop.empty() ||
            (settings.checkpoint.interval > 0 &&
             record.step_number % settings.checkpoint.interval == 0))
          write_checkpoint(control, record.step_number, wall_timer.wall_time());
        if (!stop.empty())
          {
            root_out << "Stopped after load step " << record.step_number << " ("
                     << stop << "); a checkpoint is written: continue with "
                     << "impm SCENE --resume." << std::endl;
            if (!settings.testing.enabled)
              timer.print_summary();
            return;
          }
        if (parameters.scene.stop_after_step > 0 &&
            record.step_number >= parameters.scene.stop_after_step)
          {
            root_out << "Stopped after load step " << record.step_number
                     << " (--stop-after-step); no summary is written."
                     << std::endl;
            if (!settings.testing.enabled)
              timer.print_summary();
            return;
          }
      }

    wall_timer.stop();
    pcout << "sparsity pattern kept in " << system.n_patterns_reused << " of "
          << system.n_setups << " load-step setups" << std::endl;
    if (const std::string statistics = linear_solver->statistics();
        !statistics.empty())
      pcout << statistics << std::endl;
    // The table of timings before the postprocessors' summaries: the
    // terminal's line of totals is the run's last.
    if (!settings.testing.enabled)
      timer.print_summary();
    postprocessors->finish(wall_timer.wall_time());
  }



  template <int dim>
  void
  MPMSolver<dim>::start_run()
  {
    if (!force_effects.empty())
      {
        const auto infos = material_points.infos();
        for (const auto &effect : force_effects)
          effect->initialize(infos,
                             parameters.bodies,
                             grid.cartesian(),
                             communicator);
      }
    // Every check of the scene is done before the output directory is
    // touched.
    OutputDirectory::prepare(parameters.scene.output_directory,
                             parameters.scene.name,
                             parameters.scene.file,
                             resume_state ?
                               OutputDirectory::ExistingRun::resume :
                             parameters.scene.overwrite_existing_output ?
                               OutputDirectory::ExistingRun::overwrite :
                               OutputDirectory::ExistingRun::refuse,
                             communicator);

    effect_descriptions = describe_effects();

    pcout << "Scene '" << parameters.scene.name << "' (" << dim << "D) on "
          << Utilities::MPI::n_mpi_processes(communicator) << " process(es)\n"
          << "  grid: " << grid.get_triangulation().n_global_active_cells()
          << " cells, " << grid.get_dof_handler().n_dofs() << " DoFs\n"
          << "  material points: " << material_points.n_global_points() << " ("
          << basis_name(parameters.material_points.basis) << ")\n"
          << "  bodies:\n";
    for (const auto &body : parameters.bodies)
      pcout << "    " << body.description() << '\n';
    // Known trap (doc/status.md): with one point per cell direction the
    // point's gradients are the cell's mean gradients (GIMP: the domain is
    // the whole cell; standard MPM: the point starts at the centre), which
    // leave a cell's hourglass displacements without stiffness, and GMRES
    // with AMG stalls on the system.
    if (settings.solver.linear_solver != Parameters::LinearSolverType::direct &&
        settings.solver.linear_solver != Parameters::LinearSolverType::mumps)
      for (const auto &body : parameters.bodies)
        if (body.points_per_direction == 1)
          pcout << "  note: " << body.name
                << " has one point per cell direction: its cells' "
                   "hourglass modes have no stiffness and GMRES with AMG "
                   "may not converge; use 2 or more points per cell "
                   "direction or 'Solver/Linear solver = direct'\n";
    for (const auto &coupling : couplings.list())
      for (const std::string &note :
           coupling->notes(settings.solver.linear_solver))
        pcout << "  note: " << note << '\n';
    pcout << "  effects:\n";
    for (const auto &effect : effect_descriptions)
      pcout << "    " << effect << '\n';
    if (resume_state)
      pcout << "  resumed from the checkpoint after load step "
            << resume_state->get_double("control.converged steps")
            << " (load factor "
            << resume_state->get_double("control.load factor") << ")\n";
    pcout << std::flush;
    balance_load();

    postprocessors = std::make_unique<PostprocessorManager<dim>>(
      RunContext<dim>{parameters,
                      settings.solver,
                      settings.output,
                      settings.testing,
                      settings.time,
                      grid,
                      material_points,
                      effect_descriptions,
                      !force_effects.empty(),
                      timer,
                      communicator,
                      couplings,
                      prm});
    if (resume_state)
      postprocessors->resume(*resume_state);
    else
      postprocessors->start();
  }



  template <int dim>
  std::string
  MPMSolver<dim>::reason_to_stop(const double elapsed) const
  {
    const double limit = settings.checkpoint.wall_time_limit;
    if (limit > 0. && Utilities::MPI::max(elapsed, communicator) > limit)
      return "'Checkpoint/Wall time limit' = " + number_text(limit) +
             " s passed";
    return "";
  }



  template <int dim>
  void
  MPMSolver<dim>::stop_for_signal(const LoadStepControl &control,
                                  const StepRecord      &record,
                                  const double           elapsed)
  {
    const int signal =
      Utilities::MPI::max(StopSignal::received(), communicator);
    std::ostringstream message;
    message << "Stopped by " << StopSignal::name(signal);
    if (record.converged())
      message << " after load step " << record.step_number;
    else
      message << " in load step " << record.step_number << ", abandoned after "
              << record.newton.n_iterations() << " Newton iterations";
    // The control has not taken the abandoned attempt: it holds the last
    // converged state, as do the points and the couplings.
    const unsigned int converged = control.step_number() - 1;
    if (converged == 0)
      message << "; no load step had converged, nothing is saved: start "
                 "the run again.";
    else
      {
        if (converged != checkpointed_step)
          write_checkpoint(control, converged, elapsed);
        message << "; the checkpoint after load step " << converged
                << " holds the last converged state: continue with impm "
                   "SCENE --resume.";
      }
    throw StoppedBySignal(message.str(), signal);
  }



  template <int dim>
  void
  MPMSolver<dim>::write_checkpoint(const LoadStepControl &control,
                                   const unsigned int     step_number,
                                   const double           elapsed)
  {
    TimerOutput::Scope scope(timer, "checkpoint");
    if (scene_text.empty())
      scene_text = SceneRecord::to_text(prm);
    RunState state;
    state.set("scene.name", parameters.scene.name);
    state.set("processes",
              static_cast<double>(
                Utilities::MPI::n_mpi_processes(communicator)));
    control.save(state);
    material_points.save(state);
    for (const auto &coupling : couplings.list())
      coupling->save(state);
    postprocessors->save(state, elapsed);
    Checkpoint(parameters.scene.output_directory, communicator)
      .write(
        [this](const std::string &file_name) {
          grid.save(file_name,
                    [this]() { material_points.prepare_for_checkpoint(); });
        },
        state,
        scene_text,
        estimated_checkpoint_size());
    checkpointed_step = step_number;
    pcout << "  checkpoint after load step " << step_number << std::endl;
  }



  template <int dim>
  Checkpoint::Size
  MPMSolver<dim>::estimated_checkpoint_size() const
  {
    // The largest file holds the points' serialized data and a size per
    // cell (8 bytes; 16 taken); all together add p4est's quadrant and the
    // fixed data per cell (about 40 bytes; 64 taken), the headers, the
    // state and the scene.
    const auto    &particles = material_points.particles();
    std::uintmax_t local     = 0;
    if (particles.n_locally_owned_particles() > 0)
      local =
        static_cast<std::uintmax_t>(particles.n_locally_owned_particles()) *
        particles.begin()->serialized_size_in_bytes();
    const std::uintmax_t points = Utilities::MPI::sum(local, communicator);
    const std::uintmax_t cells =
      grid.get_triangulation().n_global_active_cells();
    return {points + 64 * cells + scene_text.size() + 16384,
            points + 16 * cells};
  }



  template <int dim>
  std::vector<std::string>
  MPMSolver<dim>::describe_effects() const
  {
    std::vector<std::string> list;
    for (const auto &effect : force_effects)
      list.push_back(effect->description());
    for (const auto &face : grid.face_descriptions())
      list.push_back(face);
    for (const auto &coupling : couplings.list())
      for (const auto &line : coupling->descriptions())
        list.push_back(line);
    if (parameters.material_points.basis == BasisType::gimp &&
        parameters.material_points.update_domains)
      list.push_back("GIMP domain update with the stretch");
    if (!parameters.material_points.move_points)
      list.push_back("points held where they were seeded (no motion "
                     "through the grid)");
    return list;
  }



  template <int dim>
  void
  MPMSolver<dim>::set_up_load_step()
  {
    {
      TimerOutput::Scope scope(timer, "basis evaluation");
      system.evaluate_basis(material_points, parameters.material_points.basis);
    }
    TimerOutput::Scope scope(timer, "system setup");
    const bool same_system = couplings.set_up_system(material_points, system);
    // A kept matrix has the rows of the step before, and so its rigid-body
    // modes: the linear solver may keep what it built for it (an AMG
    // hierarchy, under its reuse rule).
    if (linear_solver->needs_near_null_space() && !same_system &&
        !problem.is_explicit())
      linear_solver->set_near_null_space(system.rigid_body_modes());
  }



  template <int dim>
  StepRecord
  MPMSolver<dim>::attempt_load_step(const LoadStepControl &control)
  {
    StepRecord record;
    record.step_number     = control.step_number();
    const StepSpan span    = load_path.span(control.start(), control.target());
    record.start           = span.start;
    record.target          = span.target;
    record.start_progress  = control.start();
    record.target_progress = control.target();
    record.end_time        = load_path.in_time() ? span.end_time : -1.;
    record.last            = control.target() >= 1.;
    record.system_dofs     = system.n_dofs();
    problem.begin(material_points, span);
    record.newton = problem.is_explicit() ? problem.explicit_step() :
                                            newton_solver.solve(problem);
    const TangentCheckResult check      = problem.take_tangent_check();
    record.tangent_difference           = check.largest_row_difference;
    record.tangent_columns_across_kinks = check.columns_across_kinks;
    if (record.converged())
      record.point_increment = problem.max_point_increment();
    record.newton.outcome =
      control.judge(record.newton.outcome, record.point_increment);
    // A converged step a coupling refuses (a rigid body that moved too far
    // or left the grid, a point left inside one) is cut or stops the run.
    for (const auto &coupling : couplings.list())
      if (record.converged())
        if (const StepRefusal refusal = coupling->refuse_step(
              material_points, system, problem.increment());
            refusal.refused())
          {
            record.newton.outcome               = NewtonOutcome::step_refused;
            record.newton.refusal               = refusal.reason;
            record.newton.smaller_step_may_pass = refusal.smaller_step_may_pass;
          }
    if (!record.converged())
      record.point_increment = 0.;
    return record;
  }



  template <int dim>
  void
  MPMSolver<dim>::accept_load_step(StepRecord &record)
  {
    if (couplings.keep_energy_balance())
      couplings.account_step_energy(system,
                                    problem.increment(),
                                    problem.work_of_loads_and_faces());
    for (const auto &coupling : couplings.list())
      coupling->accept(material_points, system, problem.increment());
    const auto reactions      = problem.reactions();
    record.reactions          = reactions.by_column;
    record.reaction_imbalance = reactions.imbalance;
    postprocessors->after_convergence(record, problem.converged_step());
    TimerOutput::Scope scope(timer, "point update");
    material_points.advance(system.point_steps,
                            problem.increment(),
                            parameters.material_points.basis ==
                                BasisType::gimp &&
                              parameters.material_points.update_domains,
                            parameters.material_points.move_points,
                            record.step_number);
    // Large per-point step data (made anew for the next step) is returned to
    // the system before the re-sorting, and the re-sorting's freed buffers
    // after it (glibc under Open MPI keeps what is freed: the 10^6-point
    // scene's peak on 2 processes fell from 1.03-1.41 to 0.86-0.92 GB a
    // process); small step data is kept (touching memory anew costs 2 %).
    const bool large =
      system.point_steps.memory_consumption() > large_step_data;
    if (large)
      {
        system.release_point_steps();
        return_free_memory();
      }
    material_points.sort_into_cells(record.step_number);
    if (large)
      return_free_memory();
  }



  template <int dim>
  void
  MPMSolver<dim>::balance_load()
  {
    if (Utilities::MPI::n_mpi_processes(communicator) == 1)
      return;
    const double before = material_points.imbalance();
    if (before <= parameters.material_points.load_imbalance_threshold)
      return;
    {
      TimerOutput::Scope scope(timer, "load balance");
      grid.repartition([this]() { material_points.prepare_for_repartition(); },
                       [this]() {
                         material_points.unpack_after_repartition();
                       });
      problem.reinit_vectors();
    }
    std::ostringstream ratios;
    ratios << std::fixed << std::setprecision(3) << before << " -> "
           << material_points.imbalance();
    pcout << "  repartitioned: most points on a process / mean " << ratios.str()
          << std::endl;
  }



  template class MPMSolver<2>;
  template class MPMSolver<3>;
} // namespace impm
