#pragma once
// A request to stop, for the whole process: the command-line program sets it on SIGINT/SIGTERM.
// Every planner polls it through its StopToken (core/stop_token.h), and the program checks it
// between stages (loading, planning, simulation, rendering), so that an interrupted command
// stops within moments and writes nothing that looks finished.
#include <atomic>

namespace cosim {

// The flag itself (lock-free, so a signal handler may set it).
std::atomic<bool>& stopRequestFlag();

inline bool stopRequested() {
  return stopRequestFlag().load(std::memory_order_relaxed);
}
inline void requestStop() {
  stopRequestFlag().store(true, std::memory_order_relaxed);
}
// For callers that go on after a stop (a library's next call); the program never does.
inline void clearStopRequest() {
  stopRequestFlag().store(false, std::memory_order_relaxed);
}

}  // namespace cosim
