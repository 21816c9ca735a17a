#pragma once
// A one-line progress bar on stderr for long renders, drawn only when stderr is a terminal
// (logs and pipes get no carriage-return noise).
#include <string>

namespace cosim {

class ProgressBar {
 public:
  // enabled: the caller wants progress; the bar still stays silent unless stderr is a tty.
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
  bool active_;
  int drawn_percent_ = -1;
  bool line_open_ = false;  // drawn, and the line not yet ended
};

}  // namespace cosim
