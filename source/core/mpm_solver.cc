#include <deal.II/base/utilities.h>

#include <impm/core/mpm_solver.h>
#include <impm/core/run.h>
#include <impm/core/scene_checks.h>
#include <impm/io/output_directory.h>

#include <filesystem>

namespace impm
{
  template <int dim>
  MPMSolver<dim>::MPMSolver(
    const Parameters::All<dim>                    &parameters,
    std::vector<std::unique_ptr<ForceEffect<dim>>> force_effects,
    const MPI_Comm                                 communicator)
    : parameters(parameters)
    , force_effects(std::move(force_effects))
    , communicator(communicator)
    , pcout(std::cout,
            Utilities::MPI::this_mpi_process(communicator) == 0 &&
              !parameters.testing.enabled)
    , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
    , grid(parameters.grid, communicator)
    , material_points(parameters.bodies, grid, communicator)
    , ghost_stabilisation(
        parameters.stabilisation.enabled ?
          std::make_unique<GhostStabilisation<dim>>(parameters.stabilisation,
                                                    grid,
                                                    parameters.bodies) :
          nullptr)
    , system(grid, communicator)
    , assembler(Assembler<dim>::create(parameters.solver.formulation,
                                       material_points,
                                       system,
                                       this->force_effects,
                                       communicator))
    , linear_solver(LinearSolver::create(parameters.solver))
    , problem(grid,
              system,
              *assembler,
              ghost_stabilisation.get(),
              *linear_solver,
              timer)
    , newton_solver(parameters.solver)
  {
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

    LoadStepControl control(parameters.solver);
    bool            new_state = true;
    while (!control.finished())
      {
        if (new_state)
          set_up_load_step();
        StepRecord record = attempt_load_step(control);
        new_state         = record.converged();
        if (record.converged())
          {
            accept_load_step(record);
            balance_load();
          }
        postprocessors->after_step(record);
        control.update(record.newton);
      }

    wall_timer.stop();
    postprocessors->finish(wall_timer.wall_time());
    if (!parameters.testing.enabled)
      timer.print_summary();
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
    pcout << "  effects:\n";
    for (const auto &effect : effect_descriptions)
      pcout << "    " << effect << '\n';
    pcout << std::flush;
    balance_load();

    postprocessors = std::make_unique<PostprocessorManager<dim>>(
      RunContext<dim>{parameters,
                      grid,
                      material_points,
                      effect_descriptions,
                      !force_effects.empty(),
                      timer,
                      communicator});
    postprocessors->start();
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
    if (ghost_stabilisation)
      list.push_back(ghost_stabilisation->description());
    if (parameters.material_points.basis == BasisType::gimp &&
        parameters.material_points.update_domains)
      list.push_back("GIMP domain update with the stretch");
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
    system.setup(material_points, ghost_stabilisation.get());
    if (linear_solver->needs_near_null_space())
      linear_solver->set_near_null_space(system.rigid_body_modes());
  }



  template <int dim>
  StepRecord
  MPMSolver<dim>::attempt_load_step(const LoadStepControl &control)
  {
    StepRecord record;
    record.step_number = control.step_number();
    record.start       = control.start();
    record.target      = control.target();
    record.system_dofs = system.n_dofs();
    problem.begin(record.start, record.target);
    record.newton = newton_solver.solve(problem);
    if (record.converged())
      record.point_increment = problem.max_point_increment();
    record.newton.outcome =
      control.judge(record.newton.outcome, record.point_increment);
    if (!record.converged())
      record.point_increment = 0.;
    return record;
  }



  template <int dim>
  void
  MPMSolver<dim>::accept_load_step(StepRecord &record)
  {
    const auto reactions      = problem.reactions();
    record.reactions          = reactions.by_column;
    record.reaction_imbalance = reactions.imbalance;
    TimerOutput::Scope scope(timer, "point update");
    material_points.advance(system.point_steps,
                            problem.increment(),
                            parameters.material_points.basis ==
                                BasisType::gimp &&
                              parameters.material_points.update_domains,
                            record.step_number);
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
    pcout << "  repartitioned: most points on a process / mean " << before
          << " -> " << material_points.imbalance() << std::endl;
  }



  template <int dim>
  void
  run_scene(ParameterHandler  &prm,
            const std::string &scene_file,
            const MPI_Comm     communicator)
  {
    Parameters::All<dim> parameters;
    parameters.parse_parameters(prm);
    parameters.scene.file = scene_file;
    SceneChecks::check(parameters, communicator);
    MPMSolver<dim> solver(parameters,
                          EffectRegistry::create_enabled<dim>(prm),
                          communicator);
    solver.run();
  }



  template class MPMSolver<2>;
  template class MPMSolver<3>;
  template void
  run_scene<2>(ParameterHandler &, const std::string &, const MPI_Comm);
  template void
  run_scene<3>(ParameterHandler &, const std::string &, const MPI_Comm);
} // namespace impm
