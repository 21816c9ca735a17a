#include "run/run_events.h"

#include <algorithm>

namespace cosim {

const char* runStageName(RunStage stage) {
  switch (stage) {
    case RunStage::Resolve:
      return "resolve";
    case RunStage::Plan:
      return "plan";
    case RunStage::BuildPilots:
      return "build_pilots";
    case RunStage::Simulate:
      return "simulate";
    case RunStage::Evaluate:
      return "evaluate";
    case RunStage::Write:
      return "write";
    case RunStage::Render:
      return "render";
  }
  return "unknown";
}

double RunEvent::fraction() const {
  if (total <= 0) return 0.0;
  return std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0);
}

void RunReporter::stage(RunStage stage) {
  stage_ = stage;
  send(RunEventKind::Stage, runStageName(stage));
}

void RunReporter::message(const std::string& text) const {
  send(RunEventKind::Message, text);
}

void RunReporter::progress(const std::string& what, int done, int total) const {
  send(RunEventKind::Progress, what, done, total);
}

void RunReporter::warning(const std::string& text) const {
  send(RunEventKind::Warning, text);
}

void RunReporter::send(RunEventKind kind, const std::string& text, int done, int total) const {
  if (!observer_) return;
  RunEvent e;
  e.kind = kind;
  e.stage = stage_;
  e.text = text;
  e.done = done;
  e.total = total;
  observer_(e);
}

}  // namespace cosim
