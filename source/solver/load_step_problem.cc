#include <impm/base/names.h>
#include <impm/solver/load_step_problem.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impm
{
  template <int dim>
  LoadStepProblem<dim>::LoadStepProblem(
    const BackgroundGrid<dim>     &grid,
    LoadStepSystem<dim>           &system,
    Assembler<dim>                &assembler,
    const GhostStabilisation<dim> *ghost_stabilisation,
    RigidContact<dim>             *rigid_contact,
    FBar<dim>                     *f_bar,
    LinearSolver                  &linear_solver,
    TimerOutput                   &timer)
    : grid(grid)
    , system(system)
    , assembler(assembler)
    , ghost_stabilisation(ghost_stabilisation)
    , rigid_contact(rigid_contact)
    , f_bar(f_bar != nullptr && f_bar->has_pressure_unknowns() ? f_bar :
                                                                 nullptr)
    , linear_solver(linear_solver)
    , timer(timer)
  {
    reinit_vectors();
  }



  template <int dim>
  void
  LoadStepProblem<dim>::reinit_vectors()
  {
    grid.reinit_vector(displacement_increment);
    grid.reinit_vector(internal_force);
    grid.reinit_vector(external_force);
  }



  template <int dim>
  void
  LoadStepProblem<dim>::begin(const double start, const double target)
  {
    displacement_increment = 0.;
    if (f_bar != nullptr)
      f_bar->reset_pressure_unknowns();
    grid.apply_prescribed_increment(target - start, displacement_increment);
    TimerOutput::Scope scope(timer, "assembly");
    assembler.assemble_external_force(target, external_force);
    external_force_norm = system.norm_in_system(external_force);
  }



  template <int dim>
  NonlinearProblem::Residual
  LoadStepProblem<dim>::evaluate_residual()
  {
    Residual residual;
    {
      TimerOutput::Scope scope(timer, "stress update");
      residual.admissible = assembler.update_stresses(displacement_increment);
    }
    if (!residual.admissible)
      return residual;

    TimerOutput::Scope scope(timer, "assembly");
    internal_force = 0.;
    assembler.add_internal_force(internal_force);
    if (ghost_stabilisation != nullptr)
      ghost_stabilisation->add_forces(displacement_increment, internal_force);
    if (rigid_contact != nullptr)
      rigid_contact->add_forces(system, displacement_increment, internal_force);
    internal_force.compress(VectorOperation::add);
    double norm = f_bar != nullptr ?
                    system.set_residual(external_force,
                                        internal_force,
                                        f_bar->pressure_residuals()) :
                    system.set_residual(external_force, internal_force);
    // Without external loads (a prescribed displacement), the residual is
    // measured against the internal forces, which carry the reactions.
    double reference = external_force_norm;
    if (has_unknowns())
      {
        unknown_residual = rigid_contact->unknown_residuals();
        norm             = std::hypot(norm, unknown_residual.l2_norm());
        reference = std::hypot(reference, rigid_contact->applied_force_norm());
      }
    if (reference == 0.)
      reference = internal_force.l2_norm();
    if (reference == 0.)
      reference = 1.;
    if (rigid_contact != nullptr)
      residual.contact_changed = rigid_contact->state_changed();
    residual.relative            = norm / reference;
    residual.norm                = norm;
    residual.internal_force_norm = internal_force.l2_norm();
    return residual;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::assemble_matrix()
  {
    TimerOutput::Scope scope(timer, "assembly");
    // The ghost penalty does not change within a load step: added after
    // the setup and then kept.
    if (!system.begin_matrix() && ghost_stabilisation != nullptr)
      {
        ghost_stabilisation->add_matrix(system, system.matrix);
        system.keep_constant_part();
      }
    assembler.add_stiffness(system.matrix);
    // The contact adds its entries through the matrix's add().
    if (rigid_contact != nullptr)
      rigid_contact->add_matrix(system, system.matrix);
    system.finish_matrix(rigid_contact != nullptr);
    if (has_unknowns())
      {
        std::vector<NodalVector> columns, rows;
        rigid_contact->add_coupling(system, columns, rows, coupling_corner);
        coupling_columns.resize(columns.size());
        coupling_rows.resize(rows.size());
        for (unsigned int j = 0; j < columns.size(); ++j)
          {
            system.copy_to_system(columns[j], coupling_columns[j]);
            system.copy_to_system(rows[j], coupling_rows[j]);
          }
      }
    if (checks_tangent)
      tangent_difference =
        std::max(tangent_difference,
                 tangent_difference_by_central_differences());
  }



  template <int dim>
  double
  LoadStepProblem<dim>::tangent_difference_by_central_differences()
  {
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    // This process's rows: (system index, local DoF).
    std::vector<std::pair<types::global_dof_index, unsigned int>> rows;
    for (unsigned int i = 0; i < grid.n_locally_owned_dofs(); ++i)
      if (system.system_index(i) != numbers::invalid_dof_index)
        rows.emplace_back(system.system_index(i), i);
    const auto internal_force_at = [&](std::vector<double> &values) {
      internal_force = 0.;
      AssertThrow(assembler.update_stresses(displacement_increment),
                  ExcMessage("Testing/Check tangent: a perturbed iterate is "
                             "inadmissible."));
      assembler.add_internal_force(internal_force);
      if (ghost_stabilisation != nullptr)
        ghost_stabilisation->add_forces(displacement_increment, internal_force);
      if (rigid_contact != nullptr)
        rigid_contact->add_forces(system,
                                  displacement_increment,
                                  internal_force);
      internal_force.compress(VectorOperation::add);
      values.resize(rows.size());
      for (unsigned int r = 0; r < rows.size(); ++r)
        values[r] = internal_force.local_element(rows[r].second);
      // F-bar's pressure rows: their equations.
      if (f_bar != nullptr)
        for (const auto &[row, residual] : f_bar->pressure_residuals())
          values.push_back(residual);
      // Then the unknowns' forces: the residual's change with the sign
      // turned (the applied force is fixed).
      if (has_unknowns())
        {
          const Vector<double> residuals = rigid_contact->unknown_residuals();
          for (unsigned int j = 0; j < residuals.size(); ++j)
            values.push_back(-residuals[j]);
        }
    };
    // F-bar's pressure rows (their unknowns follow the nodal rows).
    std::vector<types::global_dof_index> pressure_rows;
    if (f_bar != nullptr)
      for (const auto &[row, residual] : f_bar->pressure_residuals())
        pressure_rows.push_back(row);
    // A perturbation small against the cells, large against round-off.
    double cell = std::numeric_limits<double>::max();
    for (unsigned int d = 0; d < dim; ++d)
      cell = std::min(cell, grid.cartesian().cell_size[d]);
    const double perturbation = 1e-7 * cell;

    double              largest_entry = 0., largest_difference = 0.;
    std::vector<double> plus, minus;
    for (types::global_dof_index column = 0; column < system.n_dofs(); ++column)
      {
        // The owner perturbs the DoF; the ghosts follow.
        unsigned int local = numbers::invalid_unsigned_int;
        for (const auto &[index, i] : rows)
          if (index == column)
            local = i;
        // A pressure unknown's owner perturbs it by the perturbation over
        // the cell size (the pressure over E: a strain), which all
        // processes learn.
        double     pressure_scale = 0.;
        const auto perturb        = [&](const double amount) {
          displacement_increment.zero_out_ghost_values();
          if (local != numbers::invalid_unsigned_int)
            displacement_increment.local_element(local) += amount;
          displacement_increment.update_ghost_values();
          if (f_bar != nullptr)
            pressure_scale = f_bar->perturb_pressure_unknown(column, amount);
        };
        perturb(perturbation);
        const bool owns_column =
          local != numbers::invalid_unsigned_int || pressure_scale > 0.;
        const double amount_scale =
          f_bar != nullptr ? Utilities::MPI::max(pressure_scale, communicator) :
                             0.;
        internal_force_at(plus);
        // A contact whose state differs between the iterate and a
        // perturbed one (a face within the perturbation of the surface or
        // of a box's edge) has a kink there: its differences are no
        // derivative.
        bool across_kink =
          rigid_contact != nullptr && rigid_contact->state_changed();
        perturb(-2. * perturbation);
        internal_force_at(minus);
        across_kink = across_kink || (rigid_contact != nullptr &&
                                      rigid_contact->state_changed());
        perturb(perturbation);
        if (across_kink)
          {
            ++tangent_columns_across_kinks;
            continue;
          }
        const auto compare = [&](const double entry, const unsigned int r) {
          const double difference =
            (plus[r] - minus[r]) /
            (2. * perturbation * (amount_scale > 0. ? amount_scale : 1.));
          largest_entry = std::max(largest_entry, std::abs(entry));
          largest_difference =
            std::max(largest_difference, std::abs(entry - difference));
        };
        for (unsigned int r = 0; r < rows.size(); ++r)
          compare(system.matrix.el(rows[r].first, column), r);
        for (unsigned int r = 0; r < pressure_rows.size(); ++r)
          compare(system.matrix.el(pressure_rows[r], column), rows.size() + r);
        // The unknowns' rows, on the column's owner.
        if (owns_column)
          for (unsigned int j = 0; j < coupling_rows.size(); ++j)
            compare(coupling_rows[j](column),
                    rows.size() + pressure_rows.size() + j);
      }
    // The unknowns' columns: the bodies move, the DoFs stay.
    const unsigned int n_unknowns =
      has_unknowns() ? rigid_contact->unknowns().size() : 0;
    for (unsigned int j = 0; j < n_unknowns; ++j)
      {
        Vector<double> step(n_unknowns);
        const auto     move = [&](const double amount) {
          step    = 0.;
          step(j) = amount;
          rigid_contact->add_to_unknowns(step);
        };
        move(perturbation);
        internal_force_at(plus);
        bool across_kink = rigid_contact->state_changed();
        move(-2. * perturbation);
        internal_force_at(minus);
        across_kink = across_kink || rigid_contact->state_changed();
        move(perturbation);
        if (across_kink)
          {
            ++tangent_columns_across_kinks;
            continue;
          }
        for (unsigned int r = 0; r < rows.size(); ++r)
          {
            const double difference =
              (plus[r] - minus[r]) / (2. * perturbation);
            const double entry = coupling_columns[j](rows[r].first);
            largest_entry      = std::max(largest_entry, std::abs(entry));
            largest_difference =
              std::max(largest_difference, std::abs(entry - difference));
          }
        for (unsigned int i = 0; i < n_unknowns; ++i)
          {
            const unsigned int r = rows.size() + pressure_rows.size() + i;
            const double       difference =
              (plus[r] - minus[r]) / (2. * perturbation);
            largest_entry =
              std::max(largest_entry, std::abs(coupling_corner(i, j)));
            largest_difference =
              std::max(largest_difference,
                       std::abs(coupling_corner(i, j) - difference));
          }
      }
    // Back to the iterate's stresses and forces.
    std::vector<double> unused;
    internal_force_at(unused);
    largest_entry      = Utilities::MPI::max(largest_entry, communicator);
    largest_difference = Utilities::MPI::max(largest_difference, communicator);
    return largest_entry > 0. ? largest_difference / largest_entry : 0.;
  }



  template <int dim>
  LinearSolveReport
  LoadStepProblem<dim>::solve_and_update(const double relative_tolerance,
                                         const bool   estimate_condition)
  {
    if (has_unknowns())
      return solve_bordered(relative_tolerance, estimate_condition);
    TimerOutput::Scope      scope(timer, "linear solve");
    const LinearSolveReport report = linear_solver.solve({system.matrix,
                                                          system.solution,
                                                          system.rhs,
                                                          relative_tolerance,
                                                          estimate_condition});
    if (report.success)
      add_solution();
    return report;
  }



  template <int dim>
  LinearSolveReport
  LoadStepProblem<dim>::solve_bordered(const double relative_tolerance,
                                       const bool   estimate_condition)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    const auto        &unknowns = rigid_contact->unknowns();
    const unsigned int m        = unknowns.size();
    // A body no material touches in a force-driven component: nothing
    // balances its force.
    for (unsigned int j = 0; j < m; ++j)
      if (!(coupling_corner(j, j) > 0.))
        {
          LinearSolveReport report;
          report.success = false;
          report.failure =
            rigid_contact->bodies()[unknowns[j].body].name +
            " is pushed by its force in " + Names::axis(unknowns[j].component) +
            " but touches no material there: nothing balances the force "
            "(place the body on the material)";
          return report;
        }
    std::vector<TrilinosWrappers::MPI::Vector> responses(
      m, TrilinosWrappers::MPI::Vector(system.rhs));
    LinearSolveRequest request{system.matrix,
                               system.solution,
                               system.rhs,
                               relative_tolerance,
                               estimate_condition};
    for (unsigned int j = 0; j < m; ++j)
      {
        request.additional_right_hand_sides.push_back(&coupling_columns[j]);
        request.additional_solutions.push_back(&responses[j]);
      }
    LinearSolveReport report = linear_solver.solve(request);
    if (!report.success)
      return report;
    // The Schur complement of the DoFs' block, and the unknowns.
    FullMatrix<double> schur(coupling_corner);
    Vector<double>     rhs(unknown_residual);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < m; ++j)
          schur(i, j) -= coupling_rows[i] * responses[j];
        rhs(i) -= coupling_rows[i] * system.solution;
      }
    FullMatrix<double> inverse(m, m);
    inverse.invert(schur);
    Vector<double> correction(m);
    inverse.vmult(correction, rhs);
    for (unsigned int j = 0; j < m; ++j)
      if (!std::isfinite(correction(j)))
        {
          report.success = false;
          report.failure = "the rigid bodies' unknowns: a singular Schur "
                           "complement (a body pushed by a force that the "
                           "material does not hold)";
          return report;
        }
    for (unsigned int j = 0; j < m; ++j)
      system.solution.add(-correction(j), responses[j]);
    add_solution();
    rigid_contact->add_to_unknowns(correction);
    return report;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::add_solution()
  {
    system.add_solution_to(displacement_increment);
    if (f_bar != nullptr)
      f_bar->add_to_pressure_unknowns(system.solution);
  }



  template <int dim>
  double
  LoadStepProblem<dim>::max_point_increment() const
  {
    const auto &cell_size = grid.cartesian().cell_size;
    double      largest   = 0.;
    for (const PointStep<dim> &step : system.point_steps)
      {
        Tensor<1, dim> displacement;
        for (unsigned int v = 0; v < step.support.n_nodes; ++v)
          for (unsigned int i = 0; i < dim; ++i)
            displacement[i] +=
              step.support.weights[v] *
              displacement_increment.local_element(step.dofs[v * dim + i]);
        for (unsigned int d = 0; d < dim; ++d)
          largest = std::max(largest, std::abs(displacement[d]) / cell_size[d]);
      }
    largest =
      Utilities::MPI::max(largest, grid.get_triangulation().get_communicator());
    if (has_unknowns())
      largest = std::max(largest, rigid_contact->max_unknown_increment());
    return largest;
  }



  template class LoadStepProblem<2>;
  template class LoadStepProblem<3>;
} // namespace impm
