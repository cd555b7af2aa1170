// The Newton solver's line search ('Solver/Line search') on scalar problems
// whose full Newton steps fail, each solved without and with it
// (tolerance 1e-12 on |r|, 20 iterations, divergence factor 1e3).
// Expected by hand:
//   r(x) = atan(x) from x = 1.5: full Newton x <- x - (1 + x^2) atan(x)
//     overshoots ever farther (1.5, -1.694, 2.321, -5.114, ...; it
//     diverges from every |x| > 1.39175): not converged (x overflows,
//     a non-finite residual after 13 iterations). With the line
//     search the first step to -1.694 (|r| = 1.038 > 0.983) is halved to
//     x = -0.097 (|r| = 0.097, enough), then Newton converges
//     quadratically to 0: converged, one line-search residual;
//   from x = 1.39174520382 (the point whose Newton step lands on -x, a
//     2-cycle): full Newton stays on the cycle to the iteration limit;
//     with the search the first step is halved to 0 and converges;
//   r(x) = 1/x - 2 for x > 0 (x <= 0 inadmissible, as an inverted point)
//     from x = 1.2: the full step x <- 2x - 2x^2 lands on -0.48,
//     inadmissible: the solve stops there (its one iterate, not counted).
//     With the search it is halved to 0.36 (|r| = 0.778 < 1.167) and
//     converges to 0.5 (0.4608, 0.4969, 0.49998, ...: 6 iterations);
//   a problem the full step already solves (r = x - 3 from x = 0) takes
//     one iteration and no line-search residual either way;
//   a spring against a stop, r(x) = x + 9 max(x - 1, 0) - 2 (in contact for
//     x > 1, slope 1 outside and 10 inside), from x = 0: the full step
//     lands on x = 2 across the contact's switch with |r| = 9 > 2; a step
//     across which a contact changed state is taken as it is, so both
//     solves go on from x = 2 to 1.1: converged after 2 iterations with no
//     line-search residual. (Had the search judged it by the residual's
//     fall it would halve to x = 1, whose step crosses the switch again, and
//     halve to 1.125: 3 iterations and 4 line-search residuals,
//     measured.)

#include <impm/solver/newton_solver.h>
#include <impm/solver/solver_parameters.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>

using namespace impm;

namespace
{
  /** @brief A scalar r(x) = 0 with its derivative and admissible range. */
  class ScalarProblem : public NonlinearProblem
  {
  public:
    ScalarProblem(std::function<double(double)> residual_function,
                  std::function<double(double)> derivative,
                  std::function<bool(double)>   admissible,
                  const double                  start,
                  std::function<bool(double)>   in_contact = {})
      : residual_function(std::move(residual_function))
      , derivative(std::move(derivative))
      , admissible(std::move(admissible))
      , in_contact(std::move(in_contact))
      , x(start)
      , contact_state(this->in_contact && this->in_contact(start))
    {}

    Residual
    evaluate_residual() override
    {
      Residual result;
      result.admissible = admissible(x);
      if (result.admissible)
        {
          const double r             = residual_function(x);
          result.relative            = std::abs(r);
          result.norm                = std::abs(r);
          result.internal_force_norm = 1.;
          last_residual              = r;
        }
      if (in_contact)
        {
          result.contact_changed = in_contact(x) != contact_state;
          contact_state          = in_contact(x);
        }
      return result;
    }

    void
    assemble_matrix() override
    {
      slope = derivative(x);
    }

    LinearSolveReport
    solve_and_update(const double, const bool) override
    {
      correction = -last_residual / slope;
      x += correction;
      LinearSolveReport report;
      report.success = true;
      return report;
    }

    void
    move_along_last_correction(const double factor) override
    {
      x += factor * correction;
    }

    std::function<double(double)> residual_function;
    std::function<double(double)> derivative;
    std::function<bool(double)>   admissible;
    /** Whether x is in contact (empty: no contact). */
    std::function<bool(double)> in_contact;
    double                      x;
    /** The contact's state at the last evaluation. */
    bool   contact_state;
    double last_residual = 0.;
    double slope         = 1.;
    double correction    = 0.;
  };

  void
  solve(const std::string &name, ScalarProblem problem, const bool search)
  {
    Parameters::Solver parameters{};
    parameters.tolerance                 = 1e-12;
    parameters.absolute_tolerance        = 0.;
    parameters.max_iterations            = 20;
    parameters.divergence_factor         = 1e3;
    parameters.adaptive_linear_tolerance = false;
    parameters.linear_tolerance          = 1e-12;
    parameters.estimate_condition        = false;
    parameters.line_search               = search;
    const NewtonSolver solver(parameters);
    const NewtonRecord record = solver.solve(problem);
    std::cout << name << (search ? ", line search: " : ", full steps: ")
              << name_of(record.outcome) << " after " << record.n_iterations()
              << " iterations, " << record.line_search_evaluations
              << " line-search residuals";
    if (record.outcome == NewtonOutcome::converged)
      std::cout << ", x = " << std::fixed << std::setprecision(8)
                << problem.x + 0. << std::defaultfloat;
    std::cout << std::endl;
  }
} // namespace



int
main()
{
  const auto always = [](double) { return true; };
  const auto arctan = [&always](const double start) {
    return ScalarProblem([](double x) { return std::atan(x); },
                         [](double x) { return 1. / (1. + x * x); },
                         always,
                         start);
  };
  for (const bool search : {false, true})
    {
      solve("atan(x) from 1.5", arctan(1.5), search);
      solve("atan(x) from 1.39174520382", arctan(1.39174520382), search);
      solve("1/x - 2 from 1.2",
            ScalarProblem([](double x) { return 1. / x - 2.; },
                          [](double x) { return -1. / (x * x); },
                          [](double x) { return x > 0.; },
                          1.2),
            search);
      solve("x - 3 from 0",
            ScalarProblem([](double x) { return x - 3.; },
                          [](double) { return 1.; },
                          always,
                          0.),
            search);
      solve("spring against a stop from 0",
            ScalarProblem(
              [](double x) { return x + 9. * std::max(x - 1., 0.) - 2.; },
              [](double x) { return x > 1. ? 10. : 1.; },
              always,
              0.,
              [](double x) { return x > 1.; }),
            search);
    }
}
