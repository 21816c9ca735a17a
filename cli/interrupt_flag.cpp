#include "cli/interrupt_flag.h"

#include <pthread.h>

#include <csignal>

#include "core/stop_request.h"

namespace cosim {

namespace {
extern "C" void onSignal(int) {
  requestStop();
}
}  // namespace

const std::atomic<bool>& installInterruptFlag() {
  static const bool installed = [] {
    struct sigaction sa {};
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    // A shell starts background jobs with SIGINT ignored so that Ctrl-C reaches only the
    // foreground one (POSIX, Shell Command Language 2.11): an inherited SIG_IGN stays.
    struct sigaction inherited {};
    sigset_t handled;
    sigemptyset(&handled);
    sigaddset(&handled, SIGTERM);
    if (sigaction(SIGINT, nullptr, &inherited) != 0 || inherited.sa_handler != SIG_IGN) {
      sigaction(SIGINT, &sa, nullptr);
      sigaddset(&handled, SIGINT);
    }
    sigaction(SIGTERM, &sa, nullptr);
    // A blocked signal is inherited across exec as well (a launcher that blocks them in the
    // thread that starts cosim): blocked, they stayed pending and a run or a search went on to
    // its time limit. The signals handled here are unblocked; threads started later inherit that.
    pthread_sigmask(SIG_UNBLOCK, &handled, nullptr);
    return true;
  }();
  (void)installed;
  return stopRequestFlag();
}

}  // namespace cosim
