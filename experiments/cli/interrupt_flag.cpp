#include "experiments/cli/interrupt_flag.h"

#include <csignal>

namespace cosim {

namespace {
std::atomic<bool> g_interrupted{false};
extern "C" void onSignal(int) { g_interrupted.store(true); }
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
  return g_interrupted;
}

}  // namespace cosim
