#include <fsgmpm/run/interruption.h>

#include <csignal>
#include <signal.h>

namespace fsgmpm
{
  namespace Interruption
  {
    namespace
    {
      // Written by the handler, read between steps: the only kind of object
      // a signal handler may write.
      volatile std::sig_atomic_t received = 0;

      extern "C" void
      record_signal(int signal)
      {
        received = signal;
      }
    } // namespace



    void
    install_handlers()
    {
      struct sigaction action = {};
      action.sa_handler       = record_signal;
      sigemptyset(&action.sa_mask);
      // A second signal (an impatient Ctrl-C) kills as usual; SA_RESTART
      // keeps the file writes of the step going.
      action.sa_flags = SA_RESETHAND | SA_RESTART;
      sigaction(SIGTERM, &action, nullptr);
      sigaction(SIGINT, &action, nullptr);
    }



    int
    received_signal()
    {
      return received;
    }



    void
    set_received_signal(const int signal)
    {
      received = signal;
    }



    int
    exit_status(const int signal)
    {
      return 128 + signal;
    }
  } // namespace Interruption
} // namespace fsgmpm
