#include "core/stop_request.h"

namespace cosim {

namespace {
// Constant-initialised before any code runs: safe to touch from a signal handler at any time.
std::atomic<bool> g_stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free);
}  // namespace

std::atomic<bool>& stopRequestFlag() {
  return g_stop_requested;
}

}  // namespace cosim
