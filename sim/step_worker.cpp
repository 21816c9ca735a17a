#include "sim/step_worker.h"

#include <chrono>

namespace cosim {

namespace {

// How long a side spins on the shared state before it sleeps on the condition variable: longer
// than a hand-over between two running threads, far shorter than a scheduler's time slice.
constexpr auto kSpin = std::chrono::microseconds(50);

// Spins while `busy(state)` holds, at most kSpin; the state seen last.
template <typename Busy>
int spinWhile(const std::atomic<int>& state, Busy busy) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  int s = state.load(std::memory_order_acquire);
  for (int k = 0; busy(s); ++k) {
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until) break;
    s = state.load(std::memory_order_acquire);
  }
  return s;
}

}  // namespace

StepWorker::StepWorker() : thread_([this] { serve(); }) {}

StepWorker::~StepWorker() {
  wait();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.store(kStop, std::memory_order_release);
  }
  wake_.notify_one();
  thread_.join();
}

void StepWorker::start(std::function<void()> job) {
  job_ = std::move(job);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.store(kPosted, std::memory_order_release);
  }
  wake_.notify_one();
}

void StepWorker::wait() {
  int expected = kPosted;
  if (state_.compare_exchange_strong(expected, kIdle, std::memory_order_acq_rel)) {
    job_();  // the second thread has not begun it (no core for it): the caller runs it
    return;
  }
  if (expected == kIdle) return;
  const auto busy = [](int s) { return s == kRunning; };
  if (busy(spinWhile(state_, busy))) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return state_.load(std::memory_order_acquire) == kDone; });
  }
  state_.store(kIdle, std::memory_order_release);
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

void StepWorker::serve() {
  const auto idle = [](int s) { return s != kPosted && s != kStop; };
  for (;;) {
    if (idle(spinWhile(state_, idle))) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return !idle(state_.load(std::memory_order_acquire)); });
    }
    int s = kPosted;
    if (!state_.compare_exchange_strong(s, kRunning, std::memory_order_acq_rel)) {
      if (s == kStop) return;
      continue;  // the caller took the job
    }
    try {
      job_();
    } catch (...) {
      error_ = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      state_.store(kDone, std::memory_order_release);
    }
    done_.notify_one();
  }
}

}  // namespace cosim
