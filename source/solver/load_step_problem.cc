#include <deal.II/base/mpi.h>

#include <impm/base/names.h>
#include <impm/solver/load_step_problem.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

namespace impm
{
  template <int dim>
  LoadStepProblem<dim>::LoadStepProblem(const BackgroundGrid<dim> &grid,
                                        LoadStepSystem<dim>       &system,
                                        Assembler<dim>            &assembler,
                                        Couplings<dim>            &couplings,
                                        LinearSolver &linear_solver,
                                        TimerOutput  &timer)
    : grid(grid)
    , system(system)
    , assembler(assembler)
    , couplings(couplings)
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
  LoadStepProblem<dim>::begin(const MaterialPoints<dim> &material_points,
                              const StepSpan            &span)
  {
    for (const auto &coupling : couplings.list())
      coupling->begin_attempt(material_points, system, span);
    displacement_increment        = 0.;
    const bool start_residual_set = set_start_residual(span.start);
    // The start's residual matters only where a face moves in the step.
    has_start_residual = keeps_energy && start_residual_set &&
                         grid.moves_faces() && span.target != span.start;
    has_start_external_force =
      keeps_energy && span.start != span.target &&
      assembler.external_force_scales_with_load_factor();
    if (has_start_residual)
      {
        start_residual.reinit(internal_force, true);
        start_residual = internal_force;
      }
    if (has_start_external_force)
      {
        start_external_force.reinit(external_force, true);
        if (start_residual_set)
          start_external_force = external_force;
        else
          {
            TimerOutput::Scope scope(timer, "assembly");
            assembler.assemble_external_force(span.start, start_external_force);
          }
      }
    grid.apply_prescribed_increment(span.target - span.start,
                                    displacement_increment);
    warn_of_faces_without_material(span);
    TimerOutput::Scope scope(timer, "assembly");
    // The start residual's external force is the end's too where the
    // factor is the same or changes no force (the points are those of the
    // step's start in both).
    const bool same_external_force =
      start_residual_set &&
      (span.start == span.target ||
       !assembler.external_force_scales_with_load_factor());
    if (!same_external_force)
      assembler.assemble_external_force(span.target, external_force);
    external_force_norm = system.norm_in_system(external_force);
    // The internal force of a strain through the material: E_max times the
    // points' volume to the power (D - 1)/D, D = 3 in 3D and in axisymmetry
    // (rings), 2 in plane strain (per m of thickness). A step that nothing
    // drives (no load: see evaluate_residual(); no prescribed face moving)
    // is measured against at least that of a strain of 1e-5; every step's
    // residual is converged below that of 64 machine epsilons, the
    // stresses' round-off (a concrete block, E = 30 GPa, falling freely
    // stalled at a relative residual of 2e-9 in implicit steps).
    double largest_modulus = 0., volume = 0.;
    for (unsigned int p = 0; p < system.point_steps.size(); ++p)
      {
        largest_modulus =
          std::max(largest_modulus,
                   system.point_steps[p].material->elastic_modulus());
        volume += system.point_steps[p].initial_volume;
      }
    const MPI_Comm communicator = grid.get_triangulation().get_communicator();
    largest_modulus = Utilities::MPI::max(largest_modulus, communicator);
    volume          = Utilities::MPI::sum(volume, communicator);
    const double d  = (dim == 3 || grid.cartesian().axisymmetric) ? 3. : 2.;
    const double strain_force =
      largest_modulus * std::pow(volume, (d - 1.) / d);
    stress_round_off =
      64. * std::numeric_limits<double>::epsilon() * strain_force;
    unloaded_reference =
      displacement_increment.linfty_norm() > 0. ? 0. : 1e-5 * strain_force;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::warn_of_faces_without_material(const StepSpan &span)
  {
    if (!grid.moves_faces() || span.target == span.start)
      return;
    for (const unsigned int face :
         grid.prescribed_faces_without_material(system.touched()))
      if (!warned_faces[face])
        {
          warned_faces[face] = true;
          if (Utilities::MPI::this_mpi_process(
                grid.get_triangulation().get_communicator()) == 0)
            std::cerr << "Warning: from load factor " << span.start
                      << " on, no material point reaches the prescribed "
                         "grid face "
                      << Names::faces[face]
                      << " (no material lies in the cells along it): its "
                         "displacement moves nothing, and its reaction is "
                         "zero. A grid face moves only the material in the "
                         "cells it bounds; for larger motions use a rigid "
                         "body."
                      << std::endl;
        }
  }



  template <int dim>
  bool
  LoadStepProblem<dim>::set_start_residual(const double start_load_factor)
  {
    const auto &list = couplings.list();
    if (std::none_of(list.begin(), list.end(), [](const auto &coupling) {
          return coupling->needs_start_residual();
        }))
      return false;
    // The stresses of the zero increment are those of the step's start.
    {
      TimerOutput::Scope scope(timer, "stress update");
      assembler.set_start_stresses();
    }
    TimerOutput::Scope scope(timer, "assembly");
    internal_force = 0.;
    assembler.add_internal_force(internal_force);
    // The other couplings' forces of the step's start (contact, springs, a
    // base's shaking); those that ask for the residual add their own terms.
    for (const auto &coupling : list)
      if (!coupling->needs_start_residual())
        coupling->add_start_forces(system,
                                   displacement_increment,
                                   internal_force);
    internal_force.compress(VectorOperation::add);
    assembler.assemble_external_force(start_load_factor, external_force);
    internal_force -= external_force;
    internal_force.update_ghost_values();
    for (const auto &coupling : list)
      if (coupling->needs_start_residual())
        coupling->set_start_residual(internal_force);
    internal_force.zero_out_ghost_values();
    return true;
  }



  template <int dim>
  double
  LoadStepProblem<dim>::work_of_loads_and_faces() const
  {
    double work = 0.;
    for (unsigned int i = 0; i < displacement_increment.locally_owned_size();
         ++i)
      if (const double du = displacement_increment.local_element(i); du != 0.)
        {
          const double end_load = external_force.local_element(i);
          work +=
            0.5 *
            ((has_start_external_force ? start_external_force.local_element(i) :
                                         end_load) +
             end_load) *
            du;
          // A DoF outside the system that moves is moved by its face,
          // whose force on the material is the residual there.
          if (system.system_index(i) == numbers::invalid_dof_index)
            {
              const double end_force =
                internal_force.local_element(i) - end_load;
              work += 0.5 *
                      ((has_start_residual ? start_residual.local_element(i) :
                                             end_force) +
                       end_force) *
                      du;
            }
        }
    return Utilities::MPI::sum(work,
                               grid.get_triangulation().get_communicator());
  }



  template <int dim>
  NewtonRecord
  LoadStepProblem<dim>::explicit_step()
  {
    NewtonRecord record;
    record.explicit_step = true;
    {
      TimerOutput::Scope scope(timer, "point update");
      const std::string  failure =
        couplings.step_solver()->step_increment(system,
                                                displacement_increment,
                                                record.largest_time_step);
      if (!failure.empty())
        {
          record.outcome = NewtonOutcome::above_stable_step;
          record.residuals.push_back(1.);
          return record;
        }
    }
    {
      TimerOutput::Scope scope(timer, "stress update");
      if (!assembler.update_stresses(displacement_increment))
        {
          record.outcome = NewtonOutcome::inverted_point;
          record.residuals.push_back(1.);
          return record;
        }
    }
    TimerOutput::Scope scope(timer, "assembly");
    add_internal_forces();
    // The free DoFs' residual is the inertial force the step leaves.
    explicit_inertial_force = Tensor<1, dim>();
    for (unsigned int i = 0; i < internal_force.locally_owned_size(); ++i)
      if (system.system_index(i) != numbers::invalid_dof_index)
        explicit_inertial_force[grid.component(i)] +=
          external_force.local_element(i) - internal_force.local_element(i);
    for (unsigned int d = 0; d < dim; ++d)
      explicit_inertial_force[d] =
        Utilities::MPI::sum(explicit_inertial_force[d],
                            grid.get_triangulation().get_communicator());
    record.outcome = NewtonOutcome::converged;
    record.residuals.push_back(0.);
    record.last_internal_force_norm = internal_force.l2_norm();
    return record;
  }



  template <int dim>
  bool
  LoadStepProblem<dim>::update_forces()
  {
    if (!assembler.update_stresses(displacement_increment))
      return false;
    add_internal_forces();
    return true;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::add_internal_forces()
  {
    internal_force = 0.;
    assembler.add_internal_force(internal_force);
    for (const auto &coupling : couplings.list())
      coupling->add_forces(system, displacement_increment, internal_force);
    internal_force.compress(VectorOperation::add);
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
    add_internal_forces();
    row_residuals.clear();
    for (const auto &coupling : couplings.list())
      coupling->add_row_residuals(row_residuals);
    double norm =
      system.set_residual(external_force, internal_force, row_residuals);
    double reference = external_force_norm;
    for (const auto &coupling : couplings.list())
      if (const double force = coupling->reference_force(); force > 0.)
        reference = std::hypot(reference, force);
    if (couplings.n_global_unknowns() > 0)
      {
        global_residual = couplings.global_residuals();
        norm            = std::hypot(norm, global_residual.l2_norm());
      }
    // Without loads, the internal force joins the couplings' forces (the
    // reactions of a prescribed motion, or the elastic force that an
    // inertial force balances: a body pushed slowly with inertia has an
    // inertial force far below its stresses' forces, whose round-off it
    // could not resolve). With neither loads nor a coupling's force, in a
    // step that nothing drives, at least the force of a strain of 1e-5
    // (begin()): an unloaded body whose stresses are round-off (F-bar's
    // volume ratio of an unmoved patch, 1 to 1e-16) has round-off forces,
    // which no iteration lowers relative to themselves.
    const double internal_force_norm = internal_force.l2_norm();
    if (external_force_norm == 0.)
      reference = reference > 0. ?
                    std::hypot(reference, internal_force_norm) :
                    std::max(internal_force_norm, unloaded_reference);
    if (reference == 0.)
      reference = 1.;
    residual.contact_changed = couplings.state_changed();
    // Every coupling's round-off is collective: none is skipped.
    residual.round_off = stress_round_off;
    for (const auto &coupling : couplings.list())
      residual.round_off =
        std::hypot(residual.round_off, coupling->round_off_force());
    residual.relative            = norm / reference;
    residual.norm                = norm;
    residual.internal_force_norm = internal_force_norm;
    return residual;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::assemble_matrix()
  {
    TimerOutput::Scope scope(timer, "assembly");
    // The couplings' terms that do not change within a load step: added
    // after the setup and then kept.
    if (!system.begin_matrix())
      {
        bool any = false;
        for (const auto &coupling : couplings.list())
          any = coupling->add_constant_matrix(system, system.matrix) || any;
        if (any)
          system.keep_constant_part();
      }
    assembler.add_stiffness(system.matrix);
    bool added_through_matrix = false;
    for (const auto &coupling : couplings.list())
      added_through_matrix =
        coupling->add_matrix(assembler, system, system.matrix) ||
        added_through_matrix;
    system.finish_matrix(added_through_matrix);
    if (couplings.n_global_unknowns() > 0)
      {
        border.columns.clear();
        border.rows.clear();
        border.corner.reinit(couplings.n_global_unknowns(),
                             couplings.n_global_unknowns());
        unsigned int first = 0;
        for (const auto &coupling : couplings.list())
          if (const unsigned int n = coupling->n_global_unknowns(); n > 0)
            {
              std::vector<NodalVector> columns, rows;
              FullMatrix<double>       corner;
              coupling->global_coupling(system, columns, rows, corner);
              for (unsigned int j = 0; j < n; ++j)
                {
                  border.columns.emplace_back();
                  border.rows.emplace_back();
                  system.copy_to_system(columns[j], border.columns.back());
                  system.copy_to_system(rows[j], border.rows.back());
                  for (unsigned int i = 0; i < n; ++i)
                    border.corner(first + i, first + j) = corner(i, j);
                }
              first += n;
            }
      }
    if (checks_tangent)
      tangent_check_result.merge(TangentCheck<dim>(grid, system, couplings)
                                   .run(
                                     displacement_increment,
                                     internal_force,
                                     [this]() { return update_forces(); },
                                     border));
  }



  template <int dim>
  LinearSolveReport
  LoadStepProblem<dim>::solve_and_update(const double relative_tolerance,
                                         const bool   estimate_condition)
  {
    if (couplings.n_global_unknowns() > 0)
      return solve_bordered(relative_tolerance, estimate_condition);
    last_global_correction.reinit(0);
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
  void
  LoadStepProblem<dim>::move_along_last_correction(const double factor)
  {
    Assert(factor != 0., ExcInternalError());
    // The last linear solve's solution is the correction: scaled, added
    // and restored.
    system.solution *= factor;
    add_solution();
    system.solution *= 1. / factor;
    if (last_global_correction.size() > 0)
      {
        Vector<double> scaled(last_global_correction);
        scaled *= factor;
        couplings.add_to_global_unknowns(scaled);
      }
  }



  template <int dim>
  LinearSolveReport
  LoadStepProblem<dim>::solve_bordered(const double relative_tolerance,
                                       const bool   estimate_condition)
  {
    TimerOutput::Scope scope(timer, "linear solve");
    const unsigned int m = couplings.n_global_unknowns();
    // An unknown that nothing holds: nothing balances its force.
    for (unsigned int j = 0; j < m; ++j)
      if (!(border.corner(j, j) > 0.))
        {
          LinearSolveReport report;
          report.success = false;
          report.failure = couplings.unbalanced_unknown(j);
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
        request.additional_right_hand_sides.push_back(&border.columns[j]);
        request.additional_solutions.push_back(&responses[j]);
      }
    LinearSolveReport report = linear_solver.solve(request);
    if (!report.success)
      return report;
    // The Schur complement of the DoFs' block, and the unknowns.
    FullMatrix<double> schur(border.corner);
    Vector<double>     rhs(global_residual);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < m; ++j)
          schur(i, j) -= border.rows[i] * responses[j];
        rhs(i) -= border.rows[i] * system.solution;
      }
    FullMatrix<double> inverse(m, m);
    inverse.invert(schur);
    Vector<double> correction(m);
    inverse.vmult(correction, rhs);
    for (unsigned int j = 0; j < m; ++j)
      if (!std::isfinite(correction(j)))
        {
          report.success = false;
          report.failure = "the couplings' global unknowns: a singular Schur "
                           "complement (" +
                           couplings.unbalanced_unknown(j) + ")";
          return report;
        }
    for (unsigned int j = 0; j < m; ++j)
      system.solution.add(-correction(j), responses[j]);
    add_solution();
    couplings.add_to_global_unknowns(correction);
    last_global_correction = correction;
    return report;
  }



  template <int dim>
  void
  LoadStepProblem<dim>::add_solution()
  {
    system.add_solution_to(displacement_increment);
    for (const auto &coupling : couplings.list())
      coupling->add_solution(system.solution);
  }



  template <int dim>
  double
  LoadStepProblem<dim>::max_point_increment() const
  {
    const auto &cell_size = grid.cartesian().cell_size;
    double      largest   = 0.;
    for (const PointStep<dim> &step : system.point_steps)
      {
        const Tensor<1, dim> displacement =
          step.displacement(displacement_increment);
        for (unsigned int d = 0; d < dim; ++d)
          largest = std::max(largest, std::abs(displacement[d]) / cell_size[d]);
      }
    largest =
      Utilities::MPI::max(largest, grid.get_triangulation().get_communicator());
    for (const auto &coupling : couplings.list())
      largest = std::max(largest, coupling->max_unknown_increment());
    return largest;
  }



  template class LoadStepProblem<2>;
  template class LoadStepProblem<3>;
} // namespace impm
