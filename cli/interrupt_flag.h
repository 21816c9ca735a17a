#pragma once
// SIGINT/SIGTERM set the process's stop request (core/stop_request.h) that planners and long
// loops poll, so an interrupted command stops cleanly and leaves no file that looks finished.
// Commands that poll it install the handlers first thing, before loading their input.
#include <atomic>

namespace cosim {

// Installs the handlers (idempotent) and returns the flag they set (stopRequestFlag()).
const std::atomic<bool>& installInterruptFlag();

}  // namespace cosim
