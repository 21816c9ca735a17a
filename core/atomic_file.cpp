#include "core/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/crc32.h"
#include "core/input_error.h"
#include "core/output_manifest.h"
#include "core/temporary_name.h"

namespace cosim {

namespace {

[[noreturn]] void failWriting(const std::filesystem::path& target, const std::string& why) {
  throw std::runtime_error("cannot write " + target.string() + ": " + why);
}

// fsync(2) of an open descriptor. EINVAL means the file system has nothing to flush (it does not
// support syncing, e.g. some FUSE mounts): not a failure of the write.
bool flushed(int fd) {
  return ::fsync(fd) == 0 || errno == EINVAL;
}

// Flushes the file or folder at `path` (its data and, for a folder, its entries) to the disk;
// false with errno set if that fails.
bool flushPath(const std::filesystem::path& path, bool folder) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (folder ? O_DIRECTORY : 0));
  if (fd < 0) return false;
  const bool ok = flushed(fd);
  const int saved = errno;
  ::close(fd);
  errno = saved;
  return ok;
}

// The folder holding `path`'s directory entry ("." for a bare name).
std::filesystem::path folderOf(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

void removeQuietly(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove_all(p, ec);
}

// Flushes every file in the folder `dir` and the folder itself.
bool flushFolder(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir, ec)) {
    const bool folder = entry.is_directory(ec);
    if (!flushPath(entry.path(), folder)) return false;
  }
  if (ec) {
    errno = ec.value();
    return false;
  }
  return flushPath(dir, /*folder=*/true);
}

// Refuses to rename anything over a special file.
void refuseSpecialTarget(const std::filesystem::path& target) {
  if (const std::string kind = specialFileKind(target); !kind.empty())
    throw InputError(target.string(), "", notRegularProblem(kind));
}

// Refuses to replace a file (or a folder holding a file) that cosim cannot prove it wrote.
void refuseStrangerTarget(const std::filesystem::path& target) {
  const std::filesystem::path stranger = firstUnprovenOutput(target);
  if (!stranger.empty()) throw InputError(stranger.string(), "", unprovenOutputProblem());
}

void writeAtomically(const std::filesystem::path& path, const std::string& content) {
  const TemporaryFile tmp = createTemporaryFile(path, ".tmp");
  const int fd = tmp.fd;
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.path.c_str());
      failWriting(path, why);
    }
    done += static_cast<std::size_t>(n);
  }
  // close() reports errors of delayed writes on some file systems (NFS): checked as well.
  if (!flushed(fd) || ::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.path.c_str());
    failWriting(path, why);
  }
  if (::rename(tmp.path.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.path.c_str());
    failWriting(path, why);
  }
  if (!flushPath(folderOf(path), /*folder=*/true)) failWriting(path, std::strerror(errno));
}

}  // namespace

std::string specialFileKind(const std::filesystem::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "";
  if (S_ISFIFO(st.st_mode)) return "a FIFO";
  if (S_ISCHR(st.st_mode)) return "a character device";
  if (S_ISBLK(st.st_mode)) return "a block device";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "";
}

std::string notRegularProblem(const std::string& kind) {
  return "is " + kind +
         ", not a regular file: cosim writes its outputs as new regular files and would replace "
         "it; name a file instead";
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  refuseSpecialTarget(path);
  refuseStrangerTarget(path);
  writeAtomically(path, content);
  recordWrittenOutput(path, content.size(), crc32(content));
}

void writeBookkeepingFileAtomically(const std::filesystem::path& path, const std::string& content) {
  refuseSpecialTarget(path);
  writeAtomically(path, content);
}

void moveIntoPlace(const std::filesystem::path& written, const std::filesystem::path& target) {
  if (!specialFileKind(target).empty()) removeQuietly(written);
  refuseSpecialTarget(target);
  if (!firstUnprovenOutput(target).empty()) removeQuietly(written);
  refuseStrangerTarget(target);
  std::error_code ec;
  const bool folder = std::filesystem::is_directory(written, ec);
  if (!(folder ? flushFolder(written) : flushPath(written, /*folder=*/false))) {
    const std::string why = std::strerror(errno);
    removeQuietly(written);
    failWriting(target, why);
  }
  if (folder && std::filesystem::is_directory(target, ec)) {
    std::filesystem::remove_all(target, ec);
    if (ec) {
      removeQuietly(written);
      failWriting(target, "cannot replace the folder there: " + ec.message());
    }
  }
  if (::rename(written.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    removeQuietly(written);
    failWriting(target, why);
  }
  recordWrittenOutput(target);
  if (!flushPath(folderOf(target), /*folder=*/true)) failWriting(target, std::strerror(errno));
}

}  // namespace cosim
