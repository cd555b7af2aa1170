#ifndef impm_core_load_path_h
#define impm_core_load_path_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>

namespace impm
{
  using namespace dealii;

  namespace Parameters
  {
    /**
     * @brief The subsection `Time`: whether the scene runs in time, and the
     * load factor as a function of time.
     *
     * Without an end time (the default) a scene is quasi-static: the load
     * steps take the load factor from 0 to 1 and there is no time. With one,
     * the steps take the time from 0 to the end time; the loads, prescribed
     * displacements and rigid-body motions are scaled by the load factor of
     * the time (by default t / end time, the ramp of a quasi-static scene).
     */
    struct Time
    {
      /** The time at the end of the run in s (0: no time). */
      double end_time = 0.;
      /** The time step in s (0: End time / Solver/Load steps). */
      double time_step = 0.;
      /** The load factor as an expression in t (empty: t / end time). */
      std::string load_factor;
      /** The nominal time step of the run, End time over the number of
       *  steps (set with the solver's parameters; 0 without time). */
      double nominal_step = 0.;

      /** @brief Declare the subsection's entries. */
      static void
      declare_parameters(ParameterHandler &prm);

      /** @brief Read them; an inconsistent pair is a one-line InputError. */
      void
      parse_parameters(ParameterHandler &prm);

      /** @brief Whether the scene runs in time. */
      bool
      in_time() const
      {
        return end_time > 0.;
      }
    };
  } // namespace Parameters

  /**
   * @brief One load step: the load factors and times at its start and end.
   *
   * The load factors scale the loads, prescribed displacements and
   * rigid-body motions; the times are in s in a scene that runs in time
   * and equal to the load factors otherwise (a pseudo-time).
   */
  struct StepSpan
  {
    /** The load factor at the step's start. */
    double start = 0.;
    /** The load factor at the step's end. */
    double target = 0.;
    /** The time at the step's start. */
    double start_time = 0.;
    /** The time at the step's end. */
    double end_time = 0.;

    /** @brief The step's duration. */
    double
    time_step() const
    {
      return end_time - start_time;
    }
  };

  /**
   * @brief The map from the progress of a run (0 at its start, 1 at its
   * end: the step control's measure) to time and load factor.
   */
  class LoadPath
  {
  public:
    /** @brief The path a scene's `Time` subsection describes. */
    explicit LoadPath(const Parameters::Time &parameters);

    /** @brief The step from progress @p from to progress @p to. */
    StepSpan
    span(const double from, const double to) const;

    /** @brief The time at progress @p progress (the progress itself when
     *  the scene has no time). */
    double
    time(const double progress) const;

    /** @brief The load factor at progress @p progress. */
    double
    load_factor(const double progress) const;

    /** @brief Whether the scene runs in time. */
    bool
    in_time() const
    {
      return end_time > 0.;
    }

  private:
    /** The end time (0: none). */
    double end_time;
    /** The load factor's expression in t (null: the ramp t / end time). */
    std::unique_ptr<FunctionParser<1>> load_factor_of_time;
  };
} // namespace impm

#endif
