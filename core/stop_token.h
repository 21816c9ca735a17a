#pragma once
// A wall-clock time limit that planners poll: every planner honours one, so nothing hangs. It
// also expires at once when the process is asked to stop (core/stop_request.h), so that an
// interrupt reaches every planner through the check it already makes.
#include <algorithm>
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
  // A limit of `seconds` inside `outer`: it expires when `seconds` have passed or when `outer`
  // does (its own time limit or its stop request), whichever comes first. A planner's solve()
  // takes its caller's token and narrows it to the query's time limit this way.
  StopToken(double seconds, const StopToken& outer) : StopToken(seconds, outer.stop_) {
    end_ = std::min(end_, outer.end_);
  }
  // A token without a time limit: it expires only on a stop request (`stop` or the process's).
  static StopToken untimed(const std::atomic<bool>* stop = nullptr) {
    StopToken token(0.0, stop);
    token.end_ = Clock::time_point::max();
    return token;
  }

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
