// The progress at the end of each step's line: the time reached, the share
// of the run done, the attempt's wall time and the estimate of the time left.
#include <impm/postprocess/progress_clock.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace impm
{
  std::string
  format_duration(const double seconds)
  {
    char buffer[32];
    if (seconds < 0.01)
      std::snprintf(buffer, sizeof(buffer), "%.1f ms", 1e3 * seconds);
    else if (seconds < 1.)
      std::snprintf(buffer, sizeof(buffer), "%.0f ms", 1e3 * seconds);
    else if (seconds < 10.)
      std::snprintf(buffer, sizeof(buffer), "%.2f s", seconds);
    else if (seconds < 120.)
      std::snprintf(buffer, sizeof(buffer), "%.0f s", seconds);
    else if (seconds < 7200.)
      std::snprintf(buffer, sizeof(buffer), "%.0f min", seconds / 60.);
    else
      std::snprintf(buffer, sizeof(buffer), "%.1f h", seconds / 3600.);
    return buffer;
  }



  std::string
  time_text(const double time, const double step)
  {
    std::ostringstream text;
    const int          decimals =
      step > 0. ?
                 std::max(4, static_cast<int>(std::ceil(-std::log10(step) - 1e-3)) + 1) :
                 4;
    if (std::abs(time) < 1e6 && decimals <= 9)
      text << std::fixed << std::setprecision(decimals) << time;
    else
      {
        const double steps =
          step > 0. ? std::max(std::abs(time) / step, 1.) : 1.;
        const int digits =
          std::clamp(static_cast<int>(std::ceil(std::log10(steps))) + 2, 4, 15);
        text << std::scientific << std::setprecision(digits - 1) << time;
      }
    return text.str();
  }



  ProgressClock::ProgressClock()
    : last(std::chrono::steady_clock::now())
  {}



  std::string
  ProgressClock::after(const StepRecord &record)
  {
    const auto   now  = std::chrono::steady_clock::now();
    const double wall = std::chrono::duration<double>(now - last).count();
    last              = now;
    const double reached =
      record.converged() ? record.target_progress : record.start_progress;
    recent.emplace_back(wall,
                        record.converged() ?
                          record.target_progress - record.start_progress :
                          0.);
    if (recent.size() > n_recent)
      recent.pop_front();
    double recent_wall = 0., recent_progress = 0.;
    for (const auto &[seconds, progress] : recent)
      {
        recent_wall += seconds;
        recent_progress += progress;
      }
    std::ostringstream text;
    text << std::fixed;
    if (record.end_time >= 0.)
      {
        const double step =
          record.target_progress > 0. ?
            record.end_time *
              (1. - record.start_progress / record.target_progress) :
            0.;
        text << "  t " << time_text(record.end_time, step) << " s";
      }
    text << "  " << std::setprecision(1) << 100. * reached << "%"
         << "  step " << format_duration(wall);
    if (reached < 1. && recent_progress > 0.)
      text << "  left ~"
           << format_duration((1. - reached) * recent_wall / recent_progress);
    return text.str();
  }
} // namespace impm
