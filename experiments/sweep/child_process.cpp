#include "experiments/sweep/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cosim {

ChildProcess ChildProcess::start(const std::string& program, const std::vector<std::string>& args,
                                 const std::filesystem::path& log_file) {
  // Everything the child needs is prepared before fork: between fork and exec only
  // async-signal-safe calls are allowed.
  std::vector<std::string> storage;
  storage.push_back(program);
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string log = log_file.string();

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0)
    throw std::runtime_error(std::string("cannot start a job: fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::setpgid(0, 0);
    // If the sweep runner itself is killed (SIGKILL, out of memory), its jobs die with it rather
    // than write into folders a resumed sweep is reusing.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW, 0644);
    if (in >= 0) ::dup2(in, STDIN_FILENO);
    if (out >= 0) {
      ::dup2(out, STDOUT_FILENO);
      ::dup2(out, STDERR_FILENO);
    }
    ::execvp(argv[0], argv.data());
    static const char msg[] = "cosim sweep: cannot execute the job program\n";
    (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from the parent, so a signal sent at once finds the group
  ChildProcess c;
  c.pid_ = pid;
  return c;
}

bool ChildProcess::finished(int& wait_status) {
  for (;;) {
    const pid_t r = ::waitpid(pid_, &wait_status, WNOHANG);
    if (r == pid_) return true;
    if (r == 0) return false;
    if (errno != EINTR) {
      wait_status = -1;  // ECHILD: reaped elsewhere; the outcome is unknown
      return true;
    }
  }
}

int ChildProcess::wait() {
  int wait_status = 0;
  while (::waitpid(pid_, &wait_status, 0) != pid_)
    if (errno != EINTR) return -1;
  return wait_status;
}

void ChildProcess::signal(int sig) const {
  if (pid_ > 0) ::kill(-pid_, sig);
}

}  // namespace cosim
