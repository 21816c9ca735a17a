#include "render/ordered_frame_workers.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "render/run_renderer.h"

namespace cosim {

namespace {

// Frames a worker may run ahead of the one being handed over, per worker: enough that no
// worker waits for a slow neighbour's frame, few enough that memory stays bounded (a 1280x720
// frame is 2.7 MB).
constexpr int kFramesAheadPerWorker = 2;

// The shared state of one video's workers and its consumer.
class FrameHandover {
 public:
  FrameHandover(int workers, int window) : workers_(workers), window_(window) {}

  // A worker waits until frame k is within the window of frames it may run ahead; false: stop.
  bool waitForTurn(int k, std::vector<std::uint8_t>& buffer) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return stop_ || k < next_ + window_; });
    if (stop_) return false;
    if (!spare_.empty()) {
      buffer = std::move(spare_.back());
      spare_.pop_back();
    }
    return true;
  }
  void put(int k, std::vector<std::uint8_t>& frame) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ready_[k] = std::move(frame);
    }
    changed_.notify_all();
  }
  void fail(std::exception_ptr e) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = e;
      stop_ = true;
    }
    changed_.notify_all();
  }
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    changed_.notify_all();
  }
  // All workers have their contexts: none loads OpenGL entry points while another draws.
  void workerReady() {
    std::unique_lock<std::mutex> lock(mutex_);
    ++ready_workers_;
    changed_.notify_all();
    changed_.wait(lock, [&] { return stop_ || ready_workers_ == workers_; });
  }
  // The consumer takes frame `next_` (false: stopped, by an error or the interrupt).
  bool take(std::vector<std::uint8_t>& frame, const std::atomic<bool>* interrupt) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      if (error_) std::rethrow_exception(error_);
      if (interrupt && interrupt->load()) return false;
      const auto it = ready_.find(next_);
      if (it != ready_.end()) {
        if (!frame.empty()) spare_.push_back(std::move(frame));
        frame = std::move(it->second);
        ready_.erase(it);
        ++next_;
        lock.unlock();
        changed_.notify_all();
        return true;
      }
      // Woken by a finished frame; the timeout only serves the interrupt flag.
      changed_.wait_for(lock, std::chrono::milliseconds(50));
    }
  }
  void giveBack(std::vector<std::uint8_t>& frame) {
    std::lock_guard<std::mutex> lock(mutex_);
    spare_.push_back(std::move(frame));
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  const int workers_, window_;
  int ready_workers_ = 0;
  int next_ = 0;  // the next frame the consumer takes
  bool stop_ = false;
  std::exception_ptr error_;
  std::map<int, std::vector<std::uint8_t>> ready_;
  std::vector<std::vector<std::uint8_t>> spare_;
};

// mjr_makeContext loads OpenGL entry points into MuJoCo's globals: one context at a time.
std::mutex& contextCreation() {
  static std::mutex m;
  return m;
}

}  // namespace

int defaultRenderWorkers() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int renderFramesInOrder(const Scenario& scenario, const RunRecord& record,
                        const FrameSequence& sequence, int workers,
                        const std::function<void(std::vector<std::uint8_t>&)>& deliver,
                        const std::atomic<bool>* interrupt) {
  workers = std::clamp(workers, 1, std::max(1, sequence.frames));
  FrameHandover handover(workers, kFramesAheadPerWorker * workers);
  const auto work = [&](int first) {
    try {
      std::unique_ptr<RunRenderer> renderer;
      {
        std::lock_guard<std::mutex> lock(contextCreation());
        renderer = std::make_unique<RunRenderer>(scenario, record, sequence.width, sequence.height);
      }
      handover.workerReady();
      std::vector<std::uint8_t> rgb;
      for (int k = first; k < sequence.frames; k += workers) {
        if (!handover.waitForTurn(k, rgb)) break;
        renderer->render(sequence.start_time + k * sequence.seconds_per_frame, sequence.camera,
                         rgb);
        handover.put(k, rgb);
      }
      std::lock_guard<std::mutex> lock(contextCreation());
      renderer.reset();
    } catch (...) {
      handover.fail(std::current_exception());
    }
  };
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w) threads.emplace_back(work, w);
  int delivered = 0;
  std::exception_ptr error;
  try {
    std::vector<std::uint8_t> frame;
    while (delivered < sequence.frames && handover.take(frame, interrupt)) {
      deliver(frame);
      ++delivered;
    }
    if (!frame.empty()) handover.giveBack(frame);
  } catch (...) {
    error = std::current_exception();
  }
  handover.stop();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return delivered;
}

}  // namespace cosim
