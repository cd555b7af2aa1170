// The load-step control's cuts and growth (LoadStepControl), driven by
// made-up Newton outcomes: 10 nominal steps (increment 0.1), 'Easy step
// iterations' = 4, 'Steady steps before growth' = 3 (and 0 for the rule
// before it). Each line: the attempt's outcome and iterations, then the
// next attempt's start and increment. Expected by hand:
//   a failure halves the increment (0.1 -> 0.05);
//   three steps of 6 iterations in a row at 0.05 double the next (0.1);
//   that doubled step failing at once halves it and doubles the steps
//   needed (6): five more steady steps keep 0.05, the sixth grows it;
//   at the nominal increment nothing grows further;
//   after a cut an easy step (3 iterations) doubles at once;
//   with 'Steady steps before growth' = 0 steps of 6 iterations never grow
//   the increment back;
//   a failed solve whose last 5 residuals are flat below 1e-3 (a floor,
//   the axisymmetric plate's 1.5e-9) suggests 'Solver/Absolute
//   tolerance' in its message; one that cycles (0.063 and 0.11, a
//   contact's stick and slip) or still falls does not; flat residuals at
//   2e-4 of the internal forces (2 N of 1e4 N) are no round-off: the
//   message names Newton's cycling and 'Solver/Line search' (with the line
//   search on, a smaller increment).
// The floor: with 10 nominal steps and 'Minimum load step' 1e-4 the tenth
// failure in a row (0.1 / 2^10 < 1e-4) ends the run and names that entry;
// with 20,000 nominal steps (5e-5, not above 1e-4) the floor is 1/1024 of
// the nominal step, 4.8828125e-8, reached at the eleventh failure, and the
// message says so; in a time run of End time 4 s the same in seconds
// (1.953125e-7 s).

#include <impm/base/errors.h>
#include <impm/solver/load_step_control.h>
#include <impm/solver/newton_solver.h>
#include <impm/solver/solver_parameters.h>

#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace impm;

namespace
{
  Parameters::Solver
  make_parameters(const unsigned int steady_steps)
  {
    Parameters::Solver parameters{};
    parameters.n_load_steps            = 10;
    parameters.step_control            = true;
    parameters.minimum_step            = 1e-4;
    parameters.easy_iterations         = 4;
    parameters.steady_steps            = steady_steps;
    parameters.maximum_point_increment = 1.;
    return parameters;
  }

  /** One attempt: converged in @p iterations, or failed (iteration limit). */
  void
  attempt(LoadStepControl   &control,
          const bool         converged,
          const unsigned int iterations)
  {
    NewtonRecord record;
    record.outcome =
      converged ? NewtonOutcome::converged : NewtonOutcome::iteration_limit;
    record.residuals.assign(iterations + 1, 1.);
    control.update(record);
    std::cout << (converged ? "converged in " : "failed after ") << iterations
              << ": next from " << control.start() << " by "
              << control.target() - control.start() << std::endl;
  }
} // namespace



int
main()
{
  std::cout << std::setprecision(6);
  {
    std::cout << "Steady steps before growth = 3" << std::endl;
    const Parameters::Solver parameters = make_parameters(3);
    LoadStepControl          control(parameters);
    attempt(control, false, 20);
    for (unsigned int i = 0; i < 3; ++i)
      attempt(control, true, 6);
    attempt(control, false, 20);
    for (unsigned int i = 0; i < 6; ++i)
      attempt(control, true, 6);
    attempt(control, true, 6);
    attempt(control, false, 20);
    attempt(control, true, 3);
  }
  {
    std::cout << "Steady steps before growth = 0" << std::endl;
    const Parameters::Solver parameters = make_parameters(0);
    LoadStepControl          control(parameters);
    attempt(control, false, 20);
    for (unsigned int i = 0; i < 6; ++i)
      attempt(control, true, 6);
  }
  {
    std::cout << "Stalled residuals" << std::endl;
    const std::vector<std::vector<double>> cases = {
      {0.7, 0.03, 1e-6, 1.58e-9, 1.55e-9, 1.56e-9, 1.57e-9, 1.55e-9},
      {0.97, 0.066, 0.11, 0.063, 0.112, 0.063, 0.112, 0.063},
      {0.7, 0.03, 1e-6, 1e-7, 5e-8, 2e-8, 1e-8, 5e-9},
      {0.7, 1.55e-9, 1.56e-9, 1.57e-9}};
    for (const auto &residuals : cases)
      std::cout << (LoadStepControl::stalled(residuals) ? "stalled" :
                                                          "not stalled")
                << std::endl;
    Parameters::Solver parameters = make_parameters(3);
    parameters.step_control       = false;
    LoadStepControl control(parameters);
    NewtonRecord    record;
    record.outcome                  = NewtonOutcome::iteration_limit;
    record.residuals                = cases[0];
    record.last_norm                = 3.6e-5;
    record.last_internal_force_norm = 1e4;
    const auto report               = [&record](LoadStepControl &control) {
      try
        {
          control.update(record);
        }
      catch (const LoadStepFailure &failure)
        {
          const std::string text = failure.what();
          std::cout << text.substr(0, text.find(" Relative residuals"))
                    << std::endl;
        }
    };
    report(control);
    // The same flat residuals at 2e-4 of the internal forces: a cycle
    // between return regions, not round-off; the line search named, or,
    // with it on, a smaller increment.
    record.residuals = {0.7, 0.03, 2e-4, 2.1e-4, 1.9e-4, 2e-4, 2.05e-4, 2e-4};
    record.last_norm = 2.;
    report(control);
    parameters.line_search = true;
    LoadStepControl searching(parameters);
    report(searching);
  }
  {
    std::cout << "The smallest step" << std::endl;
    const auto fail_until_floor = [](const unsigned int n_steps,
                                     const double       end_time) {
      Parameters::Solver parameters = make_parameters(3);
      parameters.n_load_steps       = n_steps;
      LoadStepControl control(parameters, end_time);
      NewtonRecord    record;
      record.outcome   = NewtonOutcome::iteration_limit;
      record.residuals = {1., 0.5, 0.4};
      for (unsigned int failures = 1; failures < 100; ++failures)
        try
          {
            control.update(record);
          }
        catch (const LoadStepFailure &failure)
          {
            const std::string text  = failure.what();
            const auto        start = text.find(" The ");
            std::cout << "failure " << failures << " ends the run:"
                      << text.substr(start, text.find(" Attempts") - start)
                      << std::endl;
            return;
          }
      std::cout << "no end after 99 failures" << std::endl;
    };
    fail_until_floor(10, 0.);
    fail_until_floor(20000, 0.);
    fail_until_floor(20000, 4.);
  }
}
