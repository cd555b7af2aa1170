#include <impm/base/errors.h>
#include <impm/base/quiet_call.h>
#include <impm/core/load_path.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

namespace impm
{
  namespace Parameters
  {
    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        prm.declare_entry(
          "End time",
          "0",
          Patterns::Double(0.),
          "The time at the end of the run, in s. 0: the scene is "
          "quasi-static and has no time (its load steps take the load "
          "factor from 0 to 1). Above 0: the steps take the time from 0 to "
          "this, and the loads, prescribed displacements and rigid-body "
          "motions are scaled by 'Load factor' of the time (Inertia needs "
          "it).");
        prm.declare_entry(
          "Time step",
          "0",
          Patterns::Double(0.),
          "The nominal time step in s: the run takes End time / Time step "
          "steps (rounded up) in place of Solver/Load steps. 0: End time / "
          "Solver/Load steps.");
        prm.declare_entry(
          "Load factor",
          "",
          Patterns::Anything(),
          "The load factor as an expression in the time t (deal.II's "
          "FunctionParser, muparser syntax, with the constant pi), e.g. "
          "'1' for loads applied at once, 'sin(2*pi*t)' or "
          "'t < 0.01 ? t/0.01 : 1'. Empty: t / End time, the ramp of a "
          "quasi-static scene. Gravity set as applied at once is not "
          "scaled.");
      }
      prm.leave_subsection();
    }



    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      end_time    = prm.get_double("End time");
      time_step   = prm.get_double("Time step");
      load_factor = prm.get("Load factor");
      prm.leave_subsection();
      if (!in_time() && time_step > 0.)
        throw InputError(
          "Parameter 'Time/Time step' = " + number_text(time_step) +
          " needs 'Time/End time' above 0 (without an end "
          "time the scene has no time).");
      if (!in_time() && !load_factor.empty())
        throw InputError("Parameter 'Time/Load factor' = '" + load_factor +
                         "' needs 'Time/End time' above 0 (without an end "
                         "time the load factor is the progress of the "
                         "load steps).");
      if (time_step > end_time)
        throw InputError(
          "Parameter 'Time/Time step' = " + number_text(time_step) +
          " is not allowed: it must be at most 'Time/End "
          "time' = " +
          number_text(end_time) + ".");
      // The run counts its steps in an unsigned int: more would wrap to a
      // different number of steps (or none) without a word.
      if (time_step > 0. &&
          end_time / time_step >
            static_cast<double>(std::numeric_limits<unsigned int>::max()))
        throw InputError(
          "Parameter 'Time/Time step' = " + number_text(time_step) +
          " over 'Time/End time' = " + number_text(end_time) + " gives " +
          number_text(end_time / time_step) +
          " steps, more than a run can count (" +
          std::to_string(std::numeric_limits<unsigned int>::max()) +
          "): take a larger time step.");
      // Check the expression here, so that a wrong one is reported with
      // the scene's other input errors.
      LoadPath check(*this);
      (void)check;
    }
  } // namespace Parameters



  LoadPath::LoadPath(const Parameters::Time &parameters)
    : end_time(parameters.end_time)
  {
    if (parameters.load_factor.empty())
      return;
    load_factor_of_time = std::make_unique<FunctionParser<1>>(1);
    try
      {
        load_factor_of_time->initialize("t",
                                        parameters.load_factor,
                                        {{"pi", numbers::PI}});
        // A syntax error shows at the first evaluation (reported in the
        // line below).
        double value = std::numeric_limits<double>::quiet_NaN();
        quiet_call([&]() { value = load_factor_of_time->value(Point<1>(0.)); });
        if (!std::isfinite(value))
          throw InputError("");
      }
    catch (...)
      {
        throw InputError("Parameter 'Time/Load factor' = '" +
                         parameters.load_factor +
                         "' is not allowed: it must be an expression in t "
                         "(muparser syntax) that is finite at t = 0.");
      }
  }



  double
  LoadPath::time(const double progress) const
  {
    return in_time() ? progress * end_time : progress;
  }



  double
  LoadPath::load_factor(const double progress) const
  {
    if (!load_factor_of_time)
      return progress;
    const double value = load_factor_of_time->value(Point<1>(time(progress)));
    if (!std::isfinite(value))
      throw InputError("Parameter 'Time/Load factor' is not finite at t = " +
                       number_text(time(progress)) + " s.");
    return value;
  }



  StepSpan
  LoadPath::span(const double from, const double to) const
  {
    return {load_factor(from), load_factor(to), time(from), time(to)};
  }
} // namespace impm
