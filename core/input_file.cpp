#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/input_error.h"

namespace cosim {

namespace {

std::string megabytes(std::uintmax_t bytes) {
  return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MB";
}

// stat() the path and refuse anything but a regular file of at most max_bytes.
std::uintmax_t regularFileSize(const std::string& path, std::uintmax_t max_bytes,
                               const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path, "",
                     "cannot open " + what + ": " +
                         (errno == ENOENT ? std::string("file not found") : std::strerror(errno)));
  if (S_ISDIR(st.st_mode)) throw InputError(path, "", "is a folder, not a " + what);
  if (!S_ISREG(st.st_mode))
    throw InputError(path, "",
                     "is not a regular file (a device, FIFO or socket), so not a " + what);
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > max_bytes)
    throw InputError(path, "",
                     "is " + megabytes(size) + ", more than the " + megabytes(max_bytes) + " a " +
                         what + " may have");
  return size;
}

}  // namespace

void checkInputFile(const std::string& path, std::uintmax_t max_bytes, const std::string& what) {
  regularFileSize(path, max_bytes, what);
}

std::string readInputFile(const std::string& path, std::uintmax_t max_bytes,
                          const std::string& what) {
  regularFileSize(path, max_bytes, what);
  // O_NONBLOCK: should the path have been swapped for a FIFO since the check, open() does not
  // wait for a writer (and the read below then ends at once).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path, "", "cannot open " + what + ": " + std::strerror(errno));
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      throw InputError(path, "", "cannot read " + what + ": " + why);
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {  // it grew while being read
      ::close(fd);
      throw InputError(path, "",
                       "is more than the " + megabytes(max_bytes) + " a " + what + " may have");
    }
  }
  ::close(fd);
  return text;
}

}  // namespace cosim
