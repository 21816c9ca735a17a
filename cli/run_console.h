#pragma once
// A run's events (run/run_events.h) on stderr, as `cosim run` has always shown them: progress
// lines "cosim: TEXT" and progress bars (render/progress_bar.h) when progress is wanted, warnings
// "cosim: warning: TEXT" always.
#include <memory>
#include <string>

#include "render/progress_bar.h"
#include "run/run_events.h"

namespace cosim::cli {

class RunConsole {
 public:
  explicit RunConsole(bool progress) : progress_(progress) {}
  ~RunConsole() { finish(); }
  RunConsole(const RunConsole&) = delete;
  RunConsole& operator=(const RunConsole&) = delete;

  // The observer to put in a RunRequest; valid while this console lives.
  RunObserver observer();
  // Ends an unfinished progress bar's line: call before printing the run's results.
  void finish() { bar_.reset(); }

 private:
  void show(const RunEvent& e);

  bool progress_;
  std::unique_ptr<ProgressBar> bar_;  // of the stage in progress
  std::string bar_label_;
};

}  // namespace cosim::cli
