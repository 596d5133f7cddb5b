#include <bfemp/base/stop_signals.h>

namespace bfemp
{
  namespace
  {
    // Only a volatile sig_atomic_t may be written from a signal handler.
    volatile std::sig_atomic_t received_signal = 0;

    extern "C" void
    record_stop_signal(const int signal)
    {
      if (received_signal == 0)
        received_signal = signal;
    }
  } // namespace



  StopSignals::StopSignals()
  {
    struct sigaction action = {};
    action.sa_handler       = record_stop_signal;
    sigemptyset(&action.sa_mask);
    // SA_RESTART: file writes and waits that the signal interrupts go on
    // instead of failing with EINTR.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    for (unsigned int i = 0; i < 3; ++i)
      sigaction(handled[i], &action, &previous[i]);
  }



  StopSignals::~StopSignals()
  {
    for (unsigned int i = 0; i < 3; ++i)
      sigaction(handled[i], &previous[i], nullptr);
  }



  int
  StopSignals::received()
  {
    return received_signal;
  }



  void
  StopSignals::clear()
  {
    received_signal = 0;
  }



  std::string
  StopSignals::name(const int signal)
  {
    switch (signal)
      {
        case SIGINT:
          return "SIGINT";
        case SIGTERM:
          return "SIGTERM";
        case SIGUSR1:
          return "SIGUSR1";
        default:
          return "signal " + std::to_string(signal);
      }
  }
} // namespace bfemp
