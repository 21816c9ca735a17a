#pragma once
// Progress of a long stage on stderr, with the time it has taken and an estimate of the time
// left. On a terminal: a one-line bar redrawn in place. Elsewhere (logs, pipes): a plain line at
// most every kLogLineSeconds once the stage has run that long, so short stages say nothing and
// logs get no carriage-return noise.
#include <chrono>
#include <string>

namespace cosim {

class ProgressBar {
 public:
  static constexpr double kLogLineSeconds = 10.0;

  // enabled: the caller wants progress.
  ProgressBar(std::string label, int total, bool enabled);
  // A bar left unfinished (an interrupted render) ends its line, so the next message starts on
  // a line of its own.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  // Call after item `done` (1-based) finished; redraws at most every 1 % of the total.
  void update(int done);

 private:
  std::string label_;
  int total_;
  bool enabled_, terminal_;
  std::chrono::steady_clock::time_point start_;
  double last_line_s_ = 0.0;  // when the last plain line was written (s since start_)
  int drawn_percent_ = -1;
  bool line_open_ = false;  // drawn, and the line not yet ended
};

// "1 min 05 s", "42 s": a duration for progress lines.
std::string durationText(double seconds);

}  // namespace cosim
