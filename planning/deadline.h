#pragma once
// A wall-clock time limit that planners poll: every planner honours one, so nothing hangs. It can
// also carry an external stop request (e.g. set by a SIGINT handler), which ends it at once.
#include <atomic>
#include <chrono>

namespace cosim {

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  explicit Deadline(double seconds, const std::atomic<bool>* stop = nullptr)
      : start_(Clock::now()),
        end_(start_ +
             std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        stop_(stop) {}

  bool expired() const { return stopRequested() || Clock::now() >= end_; }
  bool stopRequested() const { return stop_ != nullptr && stop_->load(std::memory_order_relaxed); }
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(Clock::now() - start_).count();
  }

 private:
  Clock::time_point start_, end_;
  const std::atomic<bool>* stop_;
};

}  // namespace cosim
