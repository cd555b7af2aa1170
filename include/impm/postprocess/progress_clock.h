#ifndef impm_postprocess_progress_clock_h
#define impm_postprocess_progress_clock_h

#include <impm/postprocess/postprocessor.h>

#include <chrono>
#include <cstddef>
#include <deque>
#include <string>
#include <utility>

namespace impm
{
  /**
   * @brief A duration for a person: "0.4 ms", "52 ms", "3.52 s", "38 s",
   * "12 min", "3.1 h".
   */
  std::string
  format_duration(const double seconds);

  /**
   * @brief A step's time for its line, resolving a tenth of the attempt's
   * time step @p step: four decimals at least ("0.5910"), more for short
   * steps ("0.000120" for steps of 1e-5 s), and in scientific notation
   * from 1e6 s or for steps below 1e-8 s, with the digits that tell one
   * step from the next ("1.20000e-06", "1.221e+08").
   */
  std::string
  time_text(const double time, const double step);

  /**
   * @brief The wall time of each load-step attempt and an estimate of the
   * time left: the progress still to go (of 0 to 1, StepRecord's
   * target_progress) times the wall time per unit of progress over the
   * last few attempts (a cut attempt adds its time and no progress, so
   * cuts slow the estimate down as they slow the run). The terminal's step
   * lines end with its text (TerminalOutput).
   */
  class ProgressClock
  {
  public:
    /** @brief Start the clock (the run's first attempt starts now). */
    ProgressClock();

    /**
     * @brief The text after an attempt's line: "  t 0.1200 s  24.0%
     * step 0.81 s  left ~38 s" (the time only in a scene in time; no
     * estimate before any progress, none after the last step).
     */
    std::string
    after(const StepRecord &record);

  private:
    /** The attempts the estimate averages over. */
    static constexpr std::size_t n_recent = 5;
    /** The end of the last attempt. */
    std::chrono::steady_clock::time_point last;
    /** Wall time and progress of the last attempts. */
    std::deque<std::pair<double, double>> recent;
  };
} // namespace impm

#endif
