#include "render/ffmpeg_process.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace cosim {

FfmpegProcess::FfmpegProcess(const std::vector<std::string>& args) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0)
    throw std::runtime_error(std::string("cannot create a pipe to ffmpeg: ") +
                             std::strerror(errno));
  errors_ = std::tmpfile();
  if (errors_) fcntl(fileno(errors_), F_SETFD, FD_CLOEXEC);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  if (errors_) posix_spawn_file_actions_adddup2(&actions, fileno(errors_), STDERR_FILENO);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  // Its own process group (pgid = its pid); default dispositions for the signals cosim
  // ignores or handles (an ignored SIGPIPE would otherwise be inherited); nothing blocked.
  sigset_t defaults, none;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigemptyset(&none);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);

  std::vector<std::string> all = {"ffmpeg"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int rc = posix_spawnp(&pid_, "ffmpeg", &actions, &attr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  ::close(fds[0]);
  if (rc != 0) {
    ::close(fds[1]);
    if (errors_) std::fclose(errors_);
    errors_ = nullptr;
    pid_ = -1;
    throw std::runtime_error(std::string("cannot start ffmpeg (is it installed?): ") +
                             std::strerror(rc));
  }
  input_ = fds[1];
}

FfmpegProcess::~FfmpegProcess() {
  if (pid_ > 0) {
    kill();
    closeInput();
    wait();
  }
  closeInput();
  if (errors_) std::fclose(errors_);
}

bool FfmpegProcess::write(const void* data, std::size_t n) {
  if (input_ < 0) return false;
  // SIGPIPE stays blocked in this thread while it writes; the one a write to a dead ffmpeg
  // raises is taken back before unblocking, so the write just fails (EPIPE).
  sigset_t pipe_signal, old;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, &old);
  const auto* p = static_cast<const char*>(data);
  bool ok = true;
  while (n > 0) {
    const ssize_t w = ::write(input_, p, n);
    if (w < 0 && errno == EINTR) continue;  // a signal handler ran (e.g. the interrupt flag)
    if (w <= 0) {
      ok = false;
      break;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  if (!ok && errno == EPIPE && !sigismember(&old, SIGPIPE)) {
    const timespec no_wait{0, 0};
    sigtimedwait(&pipe_signal, nullptr, &no_wait);
  }
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  return ok;
}

void FfmpegProcess::closeInput() {
  if (input_ >= 0) ::close(input_);
  input_ = -1;
}

int FfmpegProcess::wait() {
  int status = -1;
  if (pid_ <= 0) return status;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  return status;
}

bool FfmpegProcess::finish() {
  closeInput();
  const int status = wait();
  return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void FfmpegProcess::kill() {
  if (pid_ > 0) ::kill(pid_, SIGKILL);
}

std::string FfmpegProcess::errorOutput() const {
  if (!errors_) return "";
  constexpr long kTail = 400;
  std::fseek(errors_, 0, SEEK_END);
  const long size = std::ftell(errors_);
  std::fseek(errors_, size > kTail ? size - kTail : 0, SEEK_SET);
  std::string text(static_cast<std::size_t>(size > kTail ? kTail : std::max(size, 0L)), '\0');
  text.resize(std::fread(text.data(), 1, text.size(), errors_));
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

}  // namespace cosim
