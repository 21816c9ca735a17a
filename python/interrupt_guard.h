#pragma once
// Ctrl-C during a long call into the library (planning, a whole run, simulating many steps).
// Python's SIGINT handler only sets a flag that the interpreter reads between bytecodes, and
// none run while C++ works. For the call's duration SIGINT instead sets the library's stop
// request (core/stop_request.h), which every planner, the simulation loops and the renderer
// poll; afterwards Python's handler is back and receives the interrupt, so the caller sees
// KeyboardInterrupt (or whatever its own SIGINT handler does).
#include <csignal>

namespace cosim::python {

class InterruptGuard {
 public:
  // Takes SIGINT over if Python handles it on this thread (the main thread; a SIGINT that is
  // ignored or left at its default stays so). Clears any stale stop request.
  InterruptGuard();
  // Gives SIGINT back to Python (the stop request is cleared; a pending interrupt is dropped:
  // an exception is already on its way).
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Call with the GIL held after the work returned. Gives SIGINT back to Python and, if it came,
  // hands it to Python's handler: throws pybind11::error_already_set if that raised
  // (KeyboardInterrupt); returns true if it came and the handler did not raise.
  bool finish();

 private:
  void restore();
  bool installed_ = false;
  struct sigaction previous_ {};
};

}  // namespace cosim::python
