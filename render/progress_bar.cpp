#include "render/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cosim {

std::string durationText(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[48];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

ProgressBar::ProgressBar(std::string label, int total, bool enabled)
    : label_(std::move(label)),
      total_(std::max(1, total)),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done) {
  if (!enabled_) return;
  done = std::clamp(done, 0, total_);
  const int percent = 100 * done / total_;
  if (percent == drawn_percent_) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The rate so far predicts the rest (frames and simulated seconds cost about the same each).
  const std::string times =
      durationText(elapsed) +
      (done > 0 && done < total_
           ? ", about " + durationText(elapsed * (total_ - done) / done) + " left"
           : std::string());
  if (!terminal_) {
    if (elapsed - last_line_s_ < kLogLineSeconds) return;
    last_line_s_ = elapsed;
    drawn_percent_ = percent;
    std::fprintf(stderr, "cosim: %s %d%% (%d/%d), %s\n", label_.c_str(), percent, done, total_,
                 times.c_str());
    return;
  }
  drawn_percent_ = percent;
  constexpr int kWidth = 30;
  const int filled = kWidth * percent / 100;
  // Trailing spaces wipe a longer line drawn before.
  std::fprintf(stderr, "\rcosim: %s [%s%s] %3d%% (%d/%d) %s   ", label_.c_str(),
               std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(), percent,
               done, total_, times.c_str());
  line_open_ = done < total_;
  if (!line_open_) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

ProgressBar::~ProgressBar() {
  if (line_open_) std::fprintf(stderr, "\n");
}

}  // namespace cosim
