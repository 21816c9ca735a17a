#include "python/interrupt_guard.h"

#include <pybind11/pybind11.h>

#include "core/stop_request.h"

namespace cosim::python {

namespace {
extern "C" void onInterrupt(int) {
  requestStop();
}

// Whether the calling thread is Python's main thread, the one Python's signal handlers run in.
bool onMainThread() {
  const pybind11::module_ threading = pybind11::module_::import("threading");
  const pybind11::object main_ident = threading.attr("main_thread")().attr("ident");
  return main_ident.equal(threading.attr("get_ident")());
}

}  // namespace

InterruptGuard::InterruptGuard() {
  clearStopRequest();
  if (!onMainThread()) return;  // SIGINT is the main thread's business
  struct sigaction current {};
  if (sigaction(SIGINT, nullptr, &current) != 0) return;
  // Python installs its handler only in the main thread of the main interpreter; a SIG_IGN or
  // SIG_DFL there is the embedding program's choice, and stays.
  if (current.sa_handler == SIG_IGN || current.sa_handler == SIG_DFL) return;
  struct sigaction mine {};
  mine.sa_handler = onInterrupt;
  sigemptyset(&mine.sa_mask);
  installed_ = sigaction(SIGINT, &mine, &previous_) == 0;
}

InterruptGuard::~InterruptGuard() {
  restore();
  clearStopRequest();
}

void InterruptGuard::restore() {
  if (installed_) sigaction(SIGINT, &previous_, nullptr);
  installed_ = false;
}

bool InterruptGuard::finish() {
  restore();
  if (!stopRequested()) return false;
  clearStopRequest();
  // As if the signal had come to Python itself: its handler (by default raising
  // KeyboardInterrupt) runs at the check.
  PyErr_SetInterruptEx(SIGINT);
  if (PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
  return true;
}

}  // namespace cosim::python
