#include <impm/base/errors.h>
#include <impm/solver/load_step_control.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace impm
{
  LoadStepControl::LoadStepControl(const Parameters::Solver &parameters,
                                   const double              end_time)
    : parameters(parameters)
    , end_time(end_time)
    , nominal_step(1. / parameters.n_load_steps)
    , step_size(nominal_step)
    , n_steady_needed(parameters.steady_steps)
  {}



  double
  LoadStepControl::smallest_step() const
  {
    return nominal_step > parameters.minimum_step ? parameters.minimum_step :
                                                    nominal_step / 1024.;
  }



  double
  LoadStepControl::explicit_limit(const NewtonRecord &record) const
  {
    if (!record.explicit_step || !(end_time > 0.) ||
        !std::isfinite(record.largest_time_step))
      return std::numeric_limits<double>::infinity();
    return record.largest_time_step / end_time;
  }



  std::string
  LoadStepControl::describe_attempt(const double progress,
                                    const double increment) const
  {
    std::ostringstream text;
    if (end_time > 0.)
      text << "t " << progress * end_time << " s (step " << increment * end_time
           << " s)";
    else
      text << "load " << progress << " (increment " << increment << ')';
    return text.str();
  }



  double
  LoadStepControl::target() const
  {
    return (load_factor + step_size > 1. - 1e-12) ? 1. :
                                                    load_factor + step_size;
  }



  NewtonOutcome
  LoadStepControl::judge(const NewtonOutcome outcome,
                         const double        point_increment) const
  {
    if (outcome == NewtonOutcome::converged && parameters.step_control &&
        point_increment > parameters.maximum_point_increment)
      return NewtonOutcome::increment_too_large;
    return outcome;
  }



  bool
  LoadStepControl::stalled(const std::vector<double> &residuals)
  {
    if (residuals.size() < stall_length + 1)
      return false;
    const auto   first = residuals.end() - stall_length;
    const double low   = *std::min_element(first, residuals.end());
    const double high  = *std::max_element(first, residuals.end());
    // Near convergence and flat: a floor, not a cycle between states (a
    // contact's stick and slip alternate between residuals apart by more).
    return high < 1e-3 && high < 1.25 * low;
  }



  void
  LoadStepControl::update(const NewtonRecord &record)
  {
    const double next = target();
    if (record.outcome == NewtonOutcome::converged)
      {
        ++n_converged;
        ++n_steady;
        untried_steady_growth = false;
        load_factor           = next;
        // An easy step doubles the next, and so does a run of steady steps
        // below the nominal increment; not to an increment a coupling
        // refused (a rigid body's motion is proportional to it).
        // An explicit step grows no further than its start's stable step
        // allows (so that a run whose stable step fell is not refused
        // every other step).
        const double grown =
          std::min({2. * step_size, nominal_step, explicit_limit(record)});
        if (!parameters.step_control || !(grown < refused_increment) ||
            !(grown > step_size))
          return;
        if (record.n_iterations() <= parameters.easy_iterations)
          {
            step_size = grown;
            n_steady  = 0;
          }
        else if (n_steady_needed > 0 && n_steady >= n_steady_needed)
          {
            step_size             = grown;
            n_steady              = 0;
            untried_steady_growth = true;
          }
        return;
      }

    failures << "\n  " << describe_attempt(next, next - load_factor) << ": "
             << record.outcome_description();
    if (!record.explicit_step)
      {
        failures << ", relative residuals:";
        for (const double residual : record.residuals)
          failures << ' ' << residual;
      }
    std::ostringstream message;
    message << "Load step " << n_converged + 1;
    if (end_time > 0.)
      message << " (from t = " << load_factor * end_time << " s to "
              << next * end_time << " s): ";
    else
      message << " (from load factor " << load_factor << " to " << next
              << "): ";
    if (record.outcome == NewtonOutcome::step_refused)
      message << record.refusal;
    else
      message << (record.explicit_step ? "the explicit step: " : "Newton ")
              << record.outcome_description() << '.';
    if (!record.smaller_step_may_pass)
      throw LoadStepFailure(message.str(), load_factor);
    if (record.outcome == NewtonOutcome::step_refused)
      refused_increment = std::min(refused_increment, next - load_factor);
    // A residual at the round-off of the internal forces cannot fall
    // further: say so, and what to do.
    if (!record.explicit_step && record.last_internal_force_norm > 0. &&
        record.last_norm < 1e-12 * record.last_internal_force_norm)
      message << " Its residual (" << record.last_norm
              << " N) is at the round-off level of the internal forces ("
              << record.last_internal_force_norm
              << " N): set 'Solver/Absolute tolerance' above it.";
    else if (record.outcome == NewtonOutcome::iteration_limit &&
             stalled(record.residuals))
      {
        message << " Its residual stalled at " << record.last_norm
                << " N (relative " << record.residuals.back()
                << ") over its last " << stall_length << " iterations";
        // Far above the internal forces' round-off (a penalty's floor
        // stays below 1e-6 of them): Newton cycles, it is not a floor.
        if (!(record.last_norm < 1e-6 * record.last_internal_force_norm))
          message << ", far above the round-off of the internal forces ("
                  << record.last_internal_force_norm
                  << " N): Newton cycles between iterates, as where points "
                     "change their return region (a plastic flow, "
                     "Mohr-Coulomb's corners, a tension cut-off); "
                  << (parameters.line_search ?
                        "a smaller increment may pass." :
                        "'Solver/Line search = true' halves the corrections "
                        "that do not lower the residual.");
        else
          message << ", a floor of round-off that iterating does not "
                     "lower: if "
                  << record.last_norm
                  << " N is negligible against the scene's forces, set "
                     "'Solver/Absolute tolerance' above it.";
      }
    if (!parameters.step_control)
      throw LoadStepFailure(message.str() +
                              " Relative residuals:" + failures.str(),
                            load_factor);
    // An explicit step above its start's stable step goes to the Courant
    // number's share of it (below the refused step, since the refusal was
    // above the stable step itself); any other failure halves the step.
    const bool above_stable_step =
      record.outcome == NewtonOutcome::above_stable_step;
    step_size = std::min(above_stable_step ? step_size : step_size / 2.,
                         explicit_limit(record));
    n_steady = 0;
    // A growth by steady steps that failed at once: the next needs twice
    // as many.
    if (untried_steady_growth && !above_stable_step)
      n_steady_needed *= 2;
    untried_steady_growth = false;
    if (step_size < smallest_step())
      {
        std::ostringstream limit;
        const bool below_nominal = smallest_step() < parameters.minimum_step;
        if (end_time > 0.)
          limit << " The time step would fall below "
                << (below_nominal ? "1/1024 of the nominal step (itself not "
                                    "above 'Solver/Minimum load step' times "
                                    "'Time/End time') = " :
                                    "'Solver/Minimum load step' times "
                                    "'Time/End time' = ")
                << smallest_step() * end_time << " s.";
        else
          limit << " The load increment would fall below "
                << (below_nominal ? "1/1024 of the nominal increment (itself "
                                    "not above 'Solver/Minimum load step') = " :
                                    "'Solver/Minimum load step' = ")
                << smallest_step() << '.';
        throw LoadStepFailure(message.str() + limit.str() +
                                " Attempts:" + failures.str(),
                              load_factor);
      }
  }



  void
  LoadStepControl::save(RunState &state) const
  {
    state.set("control.load factor", load_factor);
    state.set("control.step size", step_size);
    state.set("control.nominal step", nominal_step);
    state.set("control.converged steps", static_cast<double>(n_converged));
    if (parameters.steady_steps > 0)
      {
        state.set("control.steady steps", static_cast<double>(n_steady));
        state.set("control.steady steps needed",
                  static_cast<double>(n_steady_needed));
      }
  }



  void
  LoadStepControl::load(const RunState &state)
  {
    load_factor = state.get_double("control.load factor");
    // The steps still to come may be made finer or coarser on a resume
    // (doc/running.md): a step at its nominal size takes the scene's, a
    // cut one at most it. (Checkpoints before 2026-11-29 hold no nominal
    // step.)
    const double saved_step    = state.get_double("control.step size");
    double       saved_nominal = -1.;
    try
      {
        saved_nominal = state.get_double("control.nominal step");
      }
    catch (const CollectiveError &)
      {}
    step_size = std::abs(saved_step - saved_nominal) <= 1e-12 * saved_step ?
                  nominal_step :
                  std::min(saved_step, nominal_step);
    n_converged =
      static_cast<unsigned int>(state.get_double("control.converged steps"));
    if (parameters.steady_steps > 0)
      {
        n_steady =
          static_cast<unsigned int>(state.get_double("control.steady steps"));
        n_steady_needed = static_cast<unsigned int>(
          state.get_double("control.steady steps needed"));
      }
  }
} // namespace impm
