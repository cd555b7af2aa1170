#ifndef impm_base_stop_signal_h
#define impm_base_stop_signal_h

#include <impm/base/errors.h>

#include <string>

namespace impm
{
  /**
   * @brief The signals that stop a run: SIGTERM and SIGUSR1 (what batch
   * systems send before their time limit) and SIGINT (Ctrl-C). main()
   * installs the handlers first thing, so that a signal at any moment of a
   * run is noted, not fatal; the Newton solve checks the note before
   * every iteration (all processes together), abandons the load step in
   * progress, and the run saves its last converged state and stops with a
   * StoppedBySignal. A second SIGINT stops the process at once.
   */
  class StopSignal
  {
  public:
    /** @brief Install the handlers of SIGTERM, SIGINT and SIGUSR1. */
    static void
    install();

    /** @brief Let SIGTERM, SIGINT and SIGUSR1 through: the launcher
     *  (source/main.cc) blocks them while it loads the libraries, and one
     *  that came meanwhile is delivered now, to the installed handler. */
    static void
    unblock();

    /** @brief The signal this process received (0: none). */
    static int
    received();

    /** @brief The name of @p signal: "SIGTERM", "SIGINT" or "SIGUSR1". */
    static std::string
    name(const int signal);

    /** @brief The exit status of a run stopped by @p signal: 128 + its
     *  number, as a shell reports a process the signal ended. */
    static int
    exit_status(const int signal)
    {
      return 128 + signal;
    }
  };



  /**
   * @brief A run stopped by a signal (StopSignal), raised by all processes
   * together after the last converged state was saved. main() prints its
   * message, one line, and exits with StopSignal::exit_status().
   */
  class StoppedBySignal : public CollectiveError
  {
  public:
    /** @brief The run stopped by @p signal, with @p message for the user. */
    StoppedBySignal(const std::string &message, const int signal)
      : CollectiveError(message)
      , signal(signal)
    {}

    /** The signal's number. */
    int signal;
  };
} // namespace impm

#endif
