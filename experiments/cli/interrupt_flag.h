#pragma once
// SIGINT/SIGTERM set a flag that long loops poll, so an interrupted run stops cleanly and
// leaves no file that looks finished.
#include <atomic>

namespace cosim {

// Installs the handlers (idempotent) and returns the flag they set.
const std::atomic<bool>& installInterruptFlag();

}  // namespace cosim
