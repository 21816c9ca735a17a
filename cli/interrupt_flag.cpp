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
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
    return true;
  }();
  (void)installed;
  return stopRequestFlag();
}

}  // namespace cosim
