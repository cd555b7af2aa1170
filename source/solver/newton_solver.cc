#include <impm/solver/newton_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace impm
{
  double
  NewtonRecord::observed_order() const
  {
    double order = std::numeric_limits<double>::max();
    for (unsigned int k = 1; k + 1 < residuals.size(); ++k)
      if (residuals[k] < 1e-3 && residuals[k + 1] > 1e-10)
        order =
          std::min(order, std::log(residuals[k + 1]) / std::log(residuals[k]));
    return order;
  }



  bool
  NewtonRecord::is_measured(const double order)
  {
    return order < std::numeric_limits<double>::max();
  }



  NewtonSolver::NewtonSolver(const Parameters::Solver &parameters)
    : parameters(parameters)
  {}



  NewtonRecord
  NewtonSolver::solve(NonlinearProblem &problem) const
  {
    NewtonRecord record;
    for (unsigned int iteration = 0;; ++iteration)
      {
        const NonlinearProblem::Residual residual = problem.evaluate_residual();
        if (!residual.admissible)
          {
            record.outcome = NewtonOutcome::inverted_point;
            return record;
          }
        record.residuals.push_back(residual.relative);
        if (!std::isfinite(residual.relative))
          record.outcome = NewtonOutcome::not_finite;
        else if (residual.relative < parameters.tolerance)
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
            const double condition = problem.solve_and_update(estimate);
            if (estimate)
              record.condition_estimate = condition;
            continue;
          }
        return record;
      }
  }
} // namespace impm
