#include <impm/base/stop_signal.h>

#include <signal.h>

#include <csignal>

namespace impm
{
  namespace
  {
    /** The signal received (0: none); set by the handler. */
    volatile std::sig_atomic_t stop_signal = 0;

    extern "C" void
    note_stop_signal(int signal)
    {
      stop_signal = signal;
      // A second Ctrl-C stops at once.
      if (signal == SIGINT)
        std::signal(SIGINT, SIG_DFL);
    }
  } // namespace



  void
  StopSignal::install()
  {
    for (const int signal : {SIGTERM, SIGINT, SIGUSR1})
      std::signal(signal, note_stop_signal);
  }



  void
  StopSignal::unblock()
  {
    sigset_t signals;
    sigemptyset(&signals);
    for (const int signal : {SIGTERM, SIGINT, SIGUSR1})
      sigaddset(&signals, signal);
    sigprocmask(SIG_UNBLOCK, &signals, nullptr);
  }



  int
  StopSignal::received()
  {
    return stop_signal;
  }



  std::string
  StopSignal::name(const int signal)
  {
    switch (signal)
      {
        case SIGTERM:
          return "SIGTERM";
        case SIGINT:
          return "SIGINT";
        case SIGUSR1:
          return "SIGUSR1";
        default:
          return "signal " + std::to_string(signal);
      }
  }
} // namespace impm
