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



  bool
  NewtonSolver::meets_tolerance(
    const NonlinearProblem::Residual &residual) const
  {
    return residual.relative < parameters.tolerance ||
           residual.norm < parameters.absolute_tolerance ||
           residual.norm <= residual.round_off;
  }



  NonlinearProblem::Residual
  NewtonSolver::search_along_correction(NonlinearProblem &problem,
                                        const NonlinearProblem::Residual &full,
                                        NewtonRecord &record) const
  {
    const double previous = record.residuals.back();
    const auto   usable   = [](const NonlinearProblem::Residual &residual) {
      return residual.admissible && std::isfinite(residual.relative);
    };
    const auto enough = [&](const NonlinearProblem::Residual &residual,
                            const double                      step) {
      return usable(residual) &&
             (meets_tolerance(residual) ||
              residual.relative <= (1. - 1e-4 * step) * previous);
    };
    // A full step across which a contact changed state (stick and slip,
    // contact and separation) is taken as it is: the residual jumps where
    // the active set changes, so its fall is no measure there, and
    // halving would hold the iterate at the switch (a rigid footing then
    // cycled to the iteration limit).
    if (enough(full, 1.) || (usable(full) && full.contact_changed))
      return full;
    constexpr unsigned int     max_halvings = 5;
    NonlinearProblem::Residual residual     = full;
    double                     step = 1., best_step = 1.;
    double                     best =
      usable(full) ? full.relative : std::numeric_limits<double>::infinity();
    for (unsigned int k = 0; k < max_halvings; ++k)
      {
        problem.move_along_last_correction(-step / 2.);
        step /= 2.;
        ++record.line_search_evaluations;
        residual = problem.evaluate_residual();
        if (enough(residual, step))
          return residual;
        if (usable(residual) && residual.relative < best)
          {
            best      = residual.relative;
            best_step = step;
          }
      }
    // None admissible: the step fails as the full one would (and is cut
    // from the last converged state), no need to return to it.
    if (!std::isfinite(best))
      return residual;
    if (best_step != step)
      {
        problem.move_along_last_correction(best_step - step);
        ++record.line_search_evaluations;
        residual = problem.evaluate_residual();
      }
    return residual;
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
        NonlinearProblem::Residual residual = problem.evaluate_residual();
        if (parameters.line_search && iteration > 0)
          residual = search_along_correction(problem, residual, record);
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
        else if (meets_tolerance(residual))
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
