#include "cli/interrupt_flag.h"

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
    if (sigaction(SIGINT, nullptr, &inherited) != 0 || inherited.sa_handler != SIG_IGN)
      sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    return true;
  }();
  (void)installed;
  return stopRequestFlag();
}

}  // namespace cosim
