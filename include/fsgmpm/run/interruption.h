#ifndef fsgmpm_run_interruption_h
#define fsgmpm_run_interruption_h

namespace fsgmpm
{
  /**
   * SIGTERM and SIGINT as a request to stop: the handler only records the
   * signal, and Simulator::run() looks at it once per step, between steps,
   * so that the run stops with a complete state (its last monitors row,
   * output, a checkpoint where enabled, summary.json with termination
   * "interrupted"). A second signal of the same kind kills the process as
   * usual. A program that uses the library sees no change unless it
   * installs the handlers.
   */
  namespace Interruption
  {
    /// Install the handlers of SIGTERM and SIGINT.
    void
    install_handlers();

    /// The signal received (SIGTERM or SIGINT), or 0.
    int
    received_signal();

    /// Record @p signal as if it had been received (tests), or forget the
    /// one received with 0.
    void
    set_received_signal(const int signal);

    /// The exit status of a process stopped by @p signal as a shell
    /// reports it: 128 + the signal's number (130 for SIGINT, 143 for
    /// SIGTERM).
    int
    exit_status(const int signal);
  } // namespace Interruption
} // namespace fsgmpm

#endif
