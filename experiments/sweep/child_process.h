#pragma once
// A job as a child process (fork + exec): a crash, a hang or a runaway allocation in one job
// cannot take the sweep down. The child leads its own process group, so a timeout or an interrupt
// stops it together with anything it started (e.g. a video encoder).
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

class ChildProcess {
 public:
  // Starts `program args...` (looked up in PATH if it has no slash) with stdin from /dev/null and
  // stdout+stderr into `log_file`. Throws std::runtime_error if fork fails (exec failures show as
  // exit status 127).
  static ChildProcess start(const std::string& program, const std::vector<std::string>& args,
                            const std::filesystem::path& log_file);

  pid_t pid() const { return pid_; }
  // Non-blocking: true once the child has ended; `wait_status` is waitpid's status.
  bool finished(int& wait_status);
  // Blocks until the child exits; returns its wait status (-1 if it was reaped elsewhere).
  int wait();
  // Sends `signal` to the child's process group.
  void signal(int signal) const;

 private:
  pid_t pid_ = -1;
};

}  // namespace cosim
