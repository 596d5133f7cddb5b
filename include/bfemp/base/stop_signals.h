#ifndef bfemp_base_stop_signals_h
#define bfemp_base_stop_signals_h

#include <csignal>
#include <string>

namespace bfemp
{
  /**
   * Lets SIGINT, SIGTERM and SIGUSR1 ask a run to stop after its current
   * time step, with a checkpoint, instead of killing it. Batch systems send
   * SIGTERM some time before they kill a job at its time limit (SLURM's
   * --signal sends SIGUSR1 at a chosen lead time), and a run of many hours
   * should then lose at most the step in progress.
   *
   * While an object lives, the first of these signals is recorded; each
   * handler is installed with SA_RESETHAND, so a second signal of the same
   * kind terminates the process as usual (Ctrl-C twice still stops a run
   * at once). The destructor restores the handlers found by the
   * constructor. The record is process-wide because signal dispositions
   * are.
   */
  class StopSignals
  {
  public:
    StopSignals();

    ~StopSignals();

    StopSignals(const StopSignals &) = delete;

    StopSignals &
    operator=(const StopSignals &) = delete;

    /** The first stop signal received, 0 if none. */
    static int
    received();

    /** Forgets a received signal, for a process that runs more scenes. */
    static void
    clear();

    /** "SIGTERM" and the like. */
    static std::string
    name(const int signal);

  private:
    static constexpr int handled[3] = {SIGINT, SIGTERM, SIGUSR1};

    struct sigaction previous[3];
  };
} // namespace bfemp

#endif
