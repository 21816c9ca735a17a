#pragma once
// A second thread for the simulation loop (sim/simulation_loop.h): it runs one job while the
// calling thread runs another, and wait() returns once the job is done. Made for jobs of tens of
// microseconds to milliseconds, handed over hundreds of times a second: both sides spin briefly
// before they sleep, so a hand-over costs about a microsecond when both threads have a core,
// and nothing burns a core for long when they do not.
#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace cosim {

class StepWorker {
 public:
  StepWorker();
  ~StepWorker();
  StepWorker(const StepWorker&) = delete;
  StepWorker& operator=(const StepWorker&) = delete;

  // Starts `job` on the second thread; the previous job must have been waited for.
  void start(std::function<void()> job);
  // Returns once the job given to start() has finished (at once if none was started). If the
  // second thread has not begun the job yet (it had no core), the caller runs it itself. An
  // exception the job threw is rethrown here.
  void wait();

 private:
  void serve();

  std::function<void()> job_;
  std::exception_ptr error_;
  enum : int { kIdle, kPosted, kRunning, kDone, kStop };
  std::atomic<int> state_{kIdle};
  std::mutex mutex_;
  std::condition_variable wake_;  // the worker waits here for a job or the stop
  std::condition_variable done_;  // the caller waits here for the job's end
  std::thread thread_;
};

}  // namespace cosim
