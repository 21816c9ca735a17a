#include "core/output_dir_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "core/input_error.h"

namespace cosim {

namespace {

// The process id the holder wrote into the lock file ("" if none yet).
std::string holderOf(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string pid;
  in >> pid;
  return pid;
}

// The descriptor still names the file at `path`: an exclusive holder removes the file as it
// lets go, and a lock taken on the removed file would guard nothing.
bool stillLinked(int fd, const std::filesystem::path& path) {
  struct stat open_file {
  }, named{};
  return ::fstat(fd, &open_file) == 0 && ::stat(path.c_str(), &named) == 0 &&
         open_file.st_dev == named.st_dev && open_file.st_ino == named.st_ino;
}

}  // namespace

void OutputDirLock::acquire(const std::filesystem::path& dir, const std::string& option, Mode mode,
                            const std::string& name) {
  if (held()) return;
  const std::filesystem::path path = dir / name;
  for (;;) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw std::runtime_error("cannot lock " + dir.string() + ": " + path.string() + ": " +
                               std::strerror(errno));
    const int how = mode == Mode::Exclusive ? LOCK_EX : LOCK_SH;
    if (::flock(fd, how | LOCK_NB) != 0) {
      const int why = errno;
      ::close(fd);
      if (why != EWOULDBLOCK)
        throw std::runtime_error("cannot lock " + path.string() + ": " + std::strerror(why));
      const std::string pid = holderOf(path);
      throw InputError(dir.string(), option,
                       "the folder is in use by another cosim" +
                           (pid.empty() ? std::string() : " (pid " + pid + ")") +
                           " writing its results there; wait for it to end or choose another "
                           "folder");
    }
    if (!stillLinked(fd, path)) {  // removed by a holder that just let go: lock the new one
      ::close(fd);
      continue;
    }
    fd_ = fd;
    exclusive_ = mode == Mode::Exclusive;
    path_ = path;
    break;
  }
  // Who holds it, for the message of the next one (a shared holder writes over another's pid).
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    const ssize_t n = ::pwrite(fd_, pid.data(), pid.size(), 0);
    (void)n;  // the pid only improves a message
  }
}

OutputDirLock::~OutputDirLock() {
  if (fd_ < 0) return;
  // Removed while still locked, so that no one can lock this file and then see it go.
  if (exclusive_) ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace cosim
