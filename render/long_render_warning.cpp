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
  if (decided_ || done <= 0 || !warn_) return;
  // The rate is measured from the first frame on: the first one also pays for setting up (the
  // off-screen contexts, ffmpeg), which would inflate the estimate of a long video.
  if (first_done_ == 0) {
    first_done_ = done;
    first_elapsed_s_ = elapsed_s;
    return;
  }
  const double measured = elapsed_s - first_elapsed_s_;
  if (measured < kMeasureSeconds || done <= first_done_) return;
  decided_ = true;
  const double per_frame = measured / (done - first_done_);
  const double estimate = elapsed_s + per_frame * (total_ - done);
  if (estimate <= kWarnAboveSeconds) return;
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.3g", per_frame);
  warn_(file_ + " has " + std::to_string(total_) + " frames: at the " + rate +
        " s a frame measured so far, rendering it takes about " + durationText(estimate) +
        " (lower render.fps or raise render.speedup for a shorter video; Ctrl-C stops it)");
}

}  // namespace cosim
