#pragma once
// A warning, early in a long video, of how long rendering it will take: its frames and the time
// estimated from the frames rendered so far. Render settings within the limits can still ask for
// hours of rendering (198 817 frames, 11.6 h, measured on a laptop); the progress bar says
// nothing with --quiet and in a log only every 10 s, so such a render must not start unannounced.
#include <chrono>
#include <functional>
#include <string>

namespace cosim {

class LongRenderWarning {
 public:
  // Rendering estimated to take longer than this is announced.
  static constexpr double kWarnAboveSeconds = 600.0;
  // The estimate waits for this much rendering after the first frame.
  static constexpr double kMeasureSeconds = 2.0;

  // file: the video's name in the warning; total: its frames; warn: where the one line goes.
  LongRenderWarning(std::string file, int total, std::function<void(const std::string&)> warn);

  // After frame `done` (1-based) of the total, measured on the steady clock.
  void update(int done);
  // The same at `elapsed_s` seconds since rendering began.
  void update(int done, double elapsed_s);

 private:
  std::string file_;
  int total_;
  std::function<void(const std::string&)> warn_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool decided_ = false;  // warned, or found short enough
  int first_done_ = 0;    // the frames done at the first update, and when
  double first_elapsed_s_ = 0.0;
};

}  // namespace cosim
