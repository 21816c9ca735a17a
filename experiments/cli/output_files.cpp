#include "experiments/cli/output_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "planning/input_error.h"

namespace cosim {

void writeFileAtomically(const std::filesystem::path& path, const std::string& content) {
  // Built piece by piece: GCC 12 warns (-Wrestrict, a false positive) on a chain of operator+.
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp";
  name += std::to_string(getpid());
  const std::filesystem::path tmp = path.parent_path() / name;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmp.c_str());
      throw std::runtime_error("cannot write " + path.string() + ": " + why);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path.string() + ": " + why);
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path.string() + ": " + why);
  }
}

std::filesystem::path prepareOutputDir(const std::string& dir, const std::string& prefix) {
  std::filesystem::path out = dir;
  if (out.empty()) {
    // out/<prefix>-YYYYmmdd-HHMMSS[-N]: a new folder per run, never overwriting an old one.
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    out = std::filesystem::path("out") / (prefix + "-" + stamp);
    for (int n = 2; std::filesystem::exists(out); ++n)
      out = std::filesystem::path("out") / (prefix + "-" + stamp + "-" + std::to_string(n));
  }
  std::error_code ec;
  if (std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
    throw InputError(out.string(), "--out", "exists and is not a folder");
  std::filesystem::create_directories(out, ec);
  if (ec) throw InputError(out.string(), "--out", "cannot create folder: " + ec.message());
  if (::access(out.c_str(), W_OK) != 0)
    throw InputError(out.string(), "--out", "folder is not writable");
  return out;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace cosim
