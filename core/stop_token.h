#pragma once
// A wall-clock time limit that planners poll: every planner honours one, so nothing hangs. It
// also expires at once when the process is asked to stop (core/stop_request.h), so that an
// interrupt reaches every planner through the check it already makes.
#include <atomic>
#include <chrono>

#include "core/stop_request.h"

namespace cosim {

class StopToken {
 public:
  using Clock = std::chrono::steady_clock;
  explicit StopToken(double seconds, const std::atomic<bool>* stop = nullptr)
      : start_(Clock::now()),
        end_(start_ +
             std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        stop_(stop) {}

  bool expired() const { return stopRequested() || Clock::now() >= end_; }
  bool stopRequested() const {
    return (stop_ != nullptr && stop_->load(std::memory_order_relaxed)) || ::cosim::stopRequested();
  }
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  Clock::time_point start_, end_;
  const std::atomic<bool>* stop_;
};

}  // namespace cosim
