#pragma once
// What a run tells its front end while it goes: the stage it entered, a line for a person
// ("planning uav1 with theta_star"), the progress of a long stage (simulated seconds driven, video
// frames rendered) and warnings. The pipeline itself never prints: the cosim program turns the
// events into its stderr lines and progress bars (cli/run_console.h), a Python front end into
// whatever it shows.
#include <functional>
#include <string>

namespace cosim {

// The stages of a run, in order (run/run_pipeline.h).
enum class RunStage { Resolve, Plan, BuildPilots, Simulate, Evaluate, Write, Render };

// "resolve", "plan", "build_pilots", "simulate", "evaluate", "write", "render".
const char* runStageName(RunStage stage);

enum class RunEventKind {
  Stage,     // a stage begins (text: its name)
  Message,   // what the run is doing, for a person following it (text)
  Progress,  // `done` of `total` units of a long stage (text: what is counted)
  Warning,   // something to tell even someone not following the progress (text)
};

struct RunEvent {
  RunEventKind kind = RunEventKind::Message;
  RunStage stage = RunStage::Resolve;
  std::string text;
  int done = 0, total = 0;  // Progress only

  // Progress as a fraction in [0, 1] (0 when there is no total).
  double fraction() const;
};

using RunObserver = std::function<void(const RunEvent&)>;

// The pipeline's side of an observer: sends each event to it, if there is one, tagged with the
// stage the run is in.
class RunReporter {
 public:
  explicit RunReporter(const RunObserver& observer) : observer_(observer) {}

  // Enters `stage` and says so.
  void stage(RunStage stage);
  void message(const std::string& text) const;
  void progress(const std::string& what, int done, int total) const;
  void warning(const std::string& text) const;

 private:
  void send(RunEventKind kind, const std::string& text, int done = 0, int total = 0) const;

  const RunObserver& observer_;
  RunStage stage_ = RunStage::Resolve;
};

}  // namespace cosim
