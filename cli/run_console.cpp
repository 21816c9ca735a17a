#include "cli/run_console.h"

#include <iostream>

#include "core/input_error.h"

namespace cosim::cli {

RunObserver RunConsole::observer() {
  return [this](const RunEvent& e) { show(e); };
}

void RunConsole::show(const RunEvent& e) {
  if (e.kind == RunEventKind::Progress) {
    if (!progress_) return;
    if (!bar_ || bar_label_ != e.text) {
      bar_ = std::make_unique<ProgressBar>(e.text, e.total, true);
      bar_label_ = e.text;
    }
    bar_->update(e.done);
    return;
  }
  // Anything else ends the bar in progress first, so that its line is not run into.
  finish();
  if (e.kind == RunEventKind::Warning)
    std::cerr << "cosim: warning: " << printableText(e.text) << "\n";
  else if (e.kind == RunEventKind::Message && progress_)
    std::cerr << "cosim: " << printableText(e.text) << std::endl;
}

}  // namespace cosim::cli
