#pragma once
// One command at a time writes into an output folder: two `cosim run --out DIR` at once would
// mix one run's path and time series with the other's metrics.json. A command holds an advisory
// lock (flock(2)) on a lock file in the folder while it writes there; a second one is refused
// with the first one's process id. The kernel drops the lock when the process ends, however it
// ends (SIGKILL included), so a stale lock file never blocks a later command.
#include <filesystem>
#include <string>

namespace cosim {

class OutputDirLock {
 public:
  enum class Mode {
    Exclusive,  // the folder is this command's alone (cosim run, a whole sweep)
    Shared,     // shared with other holders in this mode (the shards of one sweep)
  };

  OutputDirLock() = default;
  OutputDirLock(const OutputDirLock&) = delete;
  OutputDirLock& operator=(const OutputDirLock&) = delete;
  // Releases the lock; an exclusive holder removes the lock file too.
  ~OutputDirLock();

  // Locks the existing folder `dir` under the lock file `name` (in `dir`). Throws InputError
  // (dir, option, "in use by another cosim (pid N) ...") if a conflicting holder has it, and
  // std::runtime_error if the lock file cannot be made. Locking a second time is a no-op.
  void acquire(const std::filesystem::path& dir, const std::string& option,
               Mode mode = Mode::Exclusive, const std::string& name = kLockFileName);

  bool held() const { return fd_ >= 0; }

  static constexpr const char* kLockFileName = ".cosim.lock";

 private:
  int fd_ = -1;
  bool exclusive_ = false;
  std::filesystem::path path_;
};

}  // namespace cosim
