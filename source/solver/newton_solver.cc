#include <impm/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace impm
{
  double
  NewtonRecord::observed_order() const
  {
    double order = std::numeric_limits<double>::max();
    for (unsigned int k = 1; k + 1 < residuals.size(); ++k)
      if (residuals[k] < 1e-3 && residuals[k + 1] > 1e-10 &&
          !(k + 1 < contact_changed.size() && contact_changed[k + 1]) &&
          !(k < asked_for_tolerance_only.size() && asked_for_tolerance_only[k]))
        order =
          std::min(order, std::log(residuals[k + 1]) / std::log(residuals[k]));
    return order;
  }



  std::string
  NewtonRecord::outcome_description() const
  {
    if (outcome == NewtonOutcome::linear_solve_failed && !linear_solves.empty())
      return name_of(outcome) + " (" + linear_solves.back().failure + ")";
    if (outcome == NewtonOutcome::step_refused)
      return name_of(outcome) + ": " + refusal;
    return name_of(outcome);
  }



  bool
  NewtonRecord::is_measured(const double order)
  {
    return order < std::numeric_limits<double>::max();
  }



  NewtonSolver::NewtonSolver(const Parameters::Solver &parameters)
    : parameters(parameters)
  {}



  double
  NewtonSolver::linear_tolerance(const double residual,
                                 const bool   contact_changed) const
  {
    if (!parameters.adaptive_linear_tolerance || contact_changed)
      return parameters.linear_tolerance;
    // Eisenstat and Walker's forcing term, and no tighter than needed to
    // bring the residual below the Newton tolerance.
    return std::max(parameters.linear_tolerance,
                    std::min(parameters.largest_linear_tolerance,
                             std::max(0.1 * residual,
                                      0.5 * parameters.tolerance / residual)));
  }



  void
  NewtonSolver::set_interruption(std::function<bool()> check)
  {
    interrupted = std::move(check);
  }



  NewtonRecord
  NewtonSolver::solve(NonlinearProblem &problem) const
  {
    NewtonRecord record;
    for (unsigned int iteration = 0;; ++iteration)
      {
        if (interrupted && interrupted())
          {
            record.outcome = NewtonOutcome::interrupted;
            return record;
          }
        const NonlinearProblem::Residual residual = problem.evaluate_residual();
        if (!residual.admissible)
          {
            record.outcome = NewtonOutcome::inverted_point;
            return record;
          }
        record.residuals.push_back(residual.relative);
        record.contact_changed.push_back(residual.contact_changed);
        record.last_norm                = residual.norm;
        record.last_internal_force_norm = residual.internal_force_norm;
        if (!std::isfinite(residual.relative))
          record.outcome = NewtonOutcome::not_finite;
        else if (residual.relative < parameters.tolerance ||
                 residual.norm < parameters.absolute_tolerance ||
                 residual.norm <= residual.round_off)
          record.outcome = NewtonOutcome::converged;
        else if (residual.relative >
                 parameters.divergence_factor * record.residuals.front())
          record.outcome = NewtonOutcome::diverged;
        else if (iteration == parameters.max_iterations)
          record.outcome = NewtonOutcome::iteration_limit;
        else
          {
            problem.assemble_matrix();
            const bool estimate =
              parameters.estimate_condition && iteration == 0;
            const double forcing_term =
              linear_tolerance(residual.relative, residual.contact_changed);
            record.linear_solves.push_back(
              problem.solve_and_update(forcing_term, estimate));
            record.asked_for_tolerance_only.push_back(
              record.linear_solves.back().iterations > 0 &&
              forcing_term > parameters.linear_tolerance &&
              forcing_term > 0.1 * residual.relative);
            if (!record.linear_solves.back().success)
              {
                record.outcome = NewtonOutcome::linear_solve_failed;
                return record;
              }
            continue;
          }
        return record;
      }
  }
} // namespace impm
