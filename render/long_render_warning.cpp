#include "render/long_render_warning.h"

#include <cstdio>

#include "render/progress_bar.h"

namespace cosim {

LongRenderWarning::LongRenderWarning(std::string file, int total,
                                     std::function<void(const std::string&)> warn)
    : file_(std::move(file)), total_(total), warn_(std::move(warn)) {}

void LongRenderWarning::update(int done) {
  update(done, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

void LongRenderWarning::update(int done, double elapsed_s) {
  if (decided_ || done <= 0 || elapsed_s < kMeasureSeconds || !warn_) return;
  decided_ = true;
  const double per_frame = elapsed_s / done;
  const double estimate = per_frame * total_;
  if (estimate <= kWarnAboveSeconds) return;
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.3g", per_frame);
  warn_(file_ + " has " + std::to_string(total_) + " frames: at the " + rate +
        " s a frame measured so far, rendering it takes about " + durationText(estimate) +
        " (lower render.fps or raise render.speedup for a shorter video; Ctrl-C stops it)");
}

}  // namespace cosim
