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
    state_.store(3, std::memory_order_release);
  }
  wake_.notify_one();
  thread_.join();
}

void StepWorker::start(std::function<void()> job) {
  job_ = std::move(job);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state_.store(1, std::memory_order_release);
  }
  wake_.notify_one();
}

void StepWorker::wait() {
  if (state_.load(std::memory_order_acquire) == 0) return;
  if (spinWhile(state_, [](int s) { return s == 1; }) == 1) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return state_.load(std::memory_order_acquire) != 1; });
  }
  state_.store(0, std::memory_order_release);
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

void StepWorker::serve() {
  for (;;) {
    int s = spinWhile(state_, [](int now) { return now != 1 && now != 3; });
    if (s != 1 && s != 3) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [this] {
        const int now = state_.load(std::memory_order_acquire);
        return now == 1 || now == 3;
      });
      s = state_.load(std::memory_order_acquire);
    }
    if (s == 3) return;
    try {
      job_();
    } catch (...) {
      error_ = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      state_.store(2, std::memory_order_release);
    }
    done_.notify_one();
  }
}

}  // namespace cosim
