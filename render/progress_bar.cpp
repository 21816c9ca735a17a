#include "render/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace cosim {

ProgressBar::ProgressBar(std::string label, int total, bool enabled)
    : label_(std::move(label)),
      total_(std::max(1, total)),
      active_(enabled && isatty(STDERR_FILENO)) {}

void ProgressBar::update(int done) {
  if (!active_) return;
  const int percent = 100 * std::clamp(done, 0, total_) / total_;
  if (percent == drawn_percent_) return;
  drawn_percent_ = percent;
  constexpr int kWidth = 40;
  const int filled = kWidth * percent / 100;
  std::fprintf(stderr, "\rcosim: %s [%s%s] %3d%% (%d/%d)", label_.c_str(),
               std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(), percent,
               std::min(done, total_), total_);
  line_open_ = done < total_;
  if (!line_open_) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

ProgressBar::~ProgressBar() {
  if (line_open_) std::fprintf(stderr, "\n");
}

}  // namespace cosim
