#include "core/temporary_name.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace cosim {

namespace {
constexpr std::size_t kMaxNameBytes = 255;   // NAME_MAX of Linux file systems
constexpr int kTemporaryNameAttempts = 100;  // names tried before giving up

// The temporary name with `suffix` (the tag, the pid and a counter) after the target's name.
std::filesystem::path nameWithSuffix(const std::filesystem::path& target,
                                     const std::string& suffix) {
  std::string name = target.filename().string();
  const std::size_t room = kMaxNameBytes - 1 - suffix.size();  // 1: the leading '.'
  if (name.size() > room) name.resize(room);
  std::string tmp = ".";  // piece by piece: GCC 12's -Wrestrict misfires on operator+ chains
  tmp += name;
  tmp += suffix;
  return target.parent_path() / tmp;
}

std::filesystem::path temporaryCandidate(const std::filesystem::path& target,
                                         const std::string& tag, int attempt) {
  std::string suffix = tag + std::to_string(::getpid());
  if (attempt > 0) {
    suffix += '-';  // piece by piece: GCC 12's -Wrestrict misfires on "-" + std::string
    suffix += std::to_string(attempt);
  }
  return nameWithSuffix(target, suffix);
}

[[noreturn]] void cannotCreateTemporary(const std::filesystem::path& target,
                                        const std::string& why) {
  throw std::runtime_error("cannot write " + target.string() + ": " + why);
}

}  // namespace

std::filesystem::path temporaryNameFor(const std::filesystem::path& target,
                                       const std::string& tag) {
  return temporaryCandidate(target, tag, 0);
}

TemporaryFile createTemporaryFile(const std::filesystem::path& target, const std::string& tag) {
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    const std::filesystem::path path = temporaryCandidate(target, tag, attempt);
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0) return {path, fd};
    if (errno != EEXIST) cannotCreateTemporary(target, std::strerror(errno));
  }
  cannotCreateTemporary(target, "every temporary name beside it is taken");
}

std::filesystem::path createTemporaryFolder(const std::filesystem::path& target,
                                            const std::string& tag) {
  for (int attempt = 0; attempt < kTemporaryNameAttempts; ++attempt) {
    const std::filesystem::path path = temporaryCandidate(target, tag, attempt);
    if (::mkdir(path.c_str(), 0755) == 0) return path;
    if (errno != EEXIST) cannotCreateTemporary(target, std::strerror(errno));
  }
  cannotCreateTemporary(target, "every temporary name beside it is taken");
}

}  // namespace cosim
