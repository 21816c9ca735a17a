#include "core/output_manifest.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/crc32.h"
#include "core/input_error.h"

namespace cosim {

namespace {

constexpr const char* kManifestFormat = "cosim output manifest 1";

struct OutputFingerprint {
  std::uintmax_t size = 0;
  std::uint32_t crc = 0;
  bool operator==(const OutputFingerprint& o) const { return size == o.size && crc == o.crc; }
};

// `path` made absolute with its folders resolved (not its last name: a symbolic link there stays
// a link), so that the ledger and the manifests name a file one way.
std::filesystem::path normalizedOutputPath(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::path abs = std::filesystem::absolute(path, ec).lexically_normal();
  std::filesystem::path parent = abs.parent_path();
  std::filesystem::path name = abs.filename();
  if (name.empty()) {  // "dir/": the folder itself
    name = parent.filename();
    parent = parent.parent_path();
  }
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(parent, ec);
  return (ec ? parent : resolved) / name;
}

// The size and CRC-32 of the regular file at `path`; nothing for a symbolic link (O_NOFOLLOW), a
// FIFO (O_NONBLOCK: never waits for a writer), a device or a missing file.
std::optional<OutputFingerprint> fingerprintOf(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return std::nullopt;
  }
  OutputFingerprint f;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ::close(fd);
      return std::nullopt;
    }
    if (n == 0) break;
    f.crc = crc32(buffer, static_cast<std::size_t>(n), f.crc);
    f.size += static_cast<std::uintmax_t>(n);
  }
  ::close(fd);
  return f;
}

std::string crcHex(std::uint32_t v) {
  char s[9];
  std::snprintf(s, sizeof s, "%08x", v);
  return s;
}

struct ManifestRecord {
  bool valid = false;
  std::string state;
  std::map<std::string, OutputFingerprint> files;  // by path relative to the manifest's folder
};

// The manifest of `dir`: not valid if it is missing or is not one cosim wrote.
ManifestRecord readManifest(const std::filesystem::path& dir) {
  ManifestRecord m;
  const std::optional<OutputFingerprint> exists = fingerprintOf(dir / kOutputManifestName);
  if (!exists) return m;
  std::FILE* f = std::fopen((dir / kOutputManifestName).c_str(), "rb");
  if (!f) return m;
  std::string text;
  char buffer[1 << 14];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
  std::fclose(f);
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object() || j.value("format", "") != kManifestFormat || !j.contains("files") ||
      !j["files"].is_object())
    return m;
  for (const auto& [name, entry] : j["files"].items()) {
    if (!entry.is_object() || !entry.contains("size") || !entry["size"].is_number_unsigned() ||
        !entry.contains("crc32") || !entry["crc32"].is_string())
      return m;
    const std::string crc = entry["crc32"].get<std::string>();
    char* end = nullptr;
    const unsigned long value = std::strtoul(crc.c_str(), &end, 16);
    if (crc.size() != 8 || end != crc.c_str() + crc.size()) return m;
    OutputFingerprint fp;
    fp.size = entry["size"].get<std::uintmax_t>();
    fp.crc = static_cast<std::uint32_t>(value);
    m.files[name] = fp;
  }
  m.state = j.value("state", "");
  m.valid = true;
  return m;
}

// This process's ledger of written files, and the manifests read so far (re-read when the
// manifest file changes).
struct OutputRecords {
  std::mutex mutex;
  std::map<std::filesystem::path, OutputFingerprint> written;
  struct Cached {
    std::optional<OutputFingerprint> file;
    ManifestRecord manifest;
  };
  std::map<std::filesystem::path, Cached> manifests;
};

OutputRecords& outputRecords() {
  static OutputRecords r;
  return r;
}

// The manifest of `dir` through the cache (caller holds the mutex).
const ManifestRecord& cachedManifest(OutputRecords& r, const std::filesystem::path& dir) {
  const std::optional<OutputFingerprint> now = fingerprintOf(dir / kOutputManifestName);
  auto it = r.manifests.find(dir);
  if (it == r.manifests.end() || !(it->second.file == now)) {
    OutputRecords::Cached c;
    c.file = now;
    if (now) c.manifest = readManifest(dir);
    it = r.manifests.insert_or_assign(dir, std::move(c)).first;
  }
  return it->second.manifest;
}

}  // namespace

void recordWrittenOutput(const std::filesystem::path& path, std::uintmax_t size,
                         std::uint32_t crc) {
  OutputRecords& r = outputRecords();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.written[normalizedOutputPath(path)] = OutputFingerprint{size, crc};
}

void recordWrittenOutput(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(std::filesystem::symlink_status(path, ec))) {
    for (const auto& e : std::filesystem::recursive_directory_iterator(path, ec))
      if (e.is_regular_file(ec) && !e.is_symlink(ec)) recordWrittenOutput(e.path());
    return;
  }
  if (const std::optional<OutputFingerprint> f = fingerprintOf(path))
    recordWrittenOutput(path, f->size, f->crc);
}

bool provenCosimOutput(const std::filesystem::path& path) {
  const std::optional<OutputFingerprint> now = fingerprintOf(path);
  if (!now) return false;
  const std::filesystem::path file = normalizedOutputPath(path);
  OutputRecords& r = outputRecords();
  std::lock_guard<std::mutex> lock(r.mutex);
  // A manifest cosim wrote is its own bookkeeping (a job folder of a sweep holds one).
  if (file.filename() == kOutputManifestName) return cachedManifest(r, file.parent_path()).valid;
  if (const auto it = r.written.find(file); it != r.written.end() && it->second == *now)
    return true;
  // The nearest manifest that lists the file decides.
  for (std::filesystem::path dir = file.parent_path();; dir = dir.parent_path()) {
    const ManifestRecord& m = cachedManifest(r, dir);
    const auto it = m.files.find(file.lexically_relative(dir).generic_string());
    if (it != m.files.end()) return it->second == *now;
    if (dir == dir.root_path() || dir.parent_path() == dir) return false;
  }
}

std::filesystem::path firstUnprovenOutput(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (ec || !std::filesystem::exists(status)) return {};
  if (!std::filesystem::is_directory(status))
    return provenCosimOutput(path) ? std::filesystem::path() : path;
  for (auto it = std::filesystem::recursive_directory_iterator(path, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
    if (!provenCosimOutput(it->path())) return it->path();
  }
  if (ec) return path;  // a folder that cannot be read proves nothing
  return {};
}

std::string unprovenOutputProblem() {
  return std::string("not written by cosim, or changed since it was (no ") + kOutputManifestName +
         " records it as it is now); cosim deletes or replaces only its own files: move it away "
         "or choose another output";
}

void requireCosimOutput(const std::filesystem::path& path, const std::string& option) {
  const std::filesystem::path stranger = firstUnprovenOutput(path);
  if (!stranger.empty()) throw InputError(stranger.string(), option, unprovenOutputProblem());
}

std::vector<std::filesystem::path> matchingOutputs(const std::filesystem::path& dir,
                                                   const std::vector<std::string>& names) {
  std::vector<std::filesystem::path> found;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return found;
  for (const std::string& n : names) {
    const std::size_t star = n.find('*');
    if (star == std::string::npos) {
      if (std::filesystem::exists(std::filesystem::symlink_status(dir / n, ec)))
        found.push_back(dir / n);
      continue;
    }
    // One '*': every entry with the text before it at its start and the text after at its end.
    const std::string prefix = n.substr(0, star), suffix = n.substr(star + 1);
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name.size() >= prefix.size() + suffix.size() && name.rfind(prefix, 0) == 0 &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
        found.push_back(e.path());
    }
  }
  return found;
}

void writeOutputManifest(const std::filesystem::path& dir, const std::string& command,
                         const std::string& state) {
  const std::filesystem::path folder = normalizedOutputPath(dir);
  // One writer of the folder's manifest at a time (the shards of a sweep share the folder).
  const int dir_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd < 0)
    throw std::runtime_error("cannot write " + (folder / kOutputManifestName).string() + ": " +
                             std::strerror(errno));
  while (::flock(dir_fd, LOCK_EX) != 0 && errno == EINTR) {
  }
  struct Unlock {
    int fd;
    ~Unlock() { ::close(fd); }  // closing drops the lock
  } unlock{dir_fd};

  const std::filesystem::path manifest_path = folder / kOutputManifestName;
  const ManifestRecord old = readManifest(folder);
  std::error_code ec;
  if (!old.valid && std::filesystem::exists(std::filesystem::symlink_status(manifest_path, ec)))
    throw InputError(manifest_path.string(), "",
                     "is not a manifest cosim wrote; cosim records its outputs under this name: "
                     "move it away");
  std::map<std::string, OutputFingerprint> files;
  for (const auto& [name, fp] : old.files)  // still there: the next check compares the bytes
    if (std::filesystem::exists(std::filesystem::symlink_status(folder / name, ec)))
      files[name] = fp;
  {
    OutputRecords& r = outputRecords();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (const auto& [path, fp] : r.written) {
      const std::filesystem::path rel = path.lexically_relative(folder);
      if (rel.empty() || *rel.begin() == ".." || rel == kOutputManifestName) continue;
      if (std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
        files[rel.generic_string()] = fp;
    }
  }
  // Nothing written here and no earlier record: a folder cosim left alone gets no manifest.
  if (files.empty() && !old.valid) return;
  nlohmann::json j;
  j["format"] = kManifestFormat;
  j["command"] = command;
  j["state"] = state;
  nlohmann::json listed = nlohmann::json::object();
  for (const auto& [name, fp] : files)
    listed[name] = {{"size", fp.size}, {"crc32", crcHex(fp.crc)}};
  j["files"] = std::move(listed);
  writeBookkeepingFileAtomically(manifest_path, j.dump(1) + "\n");
}

void writeOutputManifestOf(const std::filesystem::path& output, const std::string& command) {
  const std::filesystem::path file = normalizedOutputPath(output);
  writeOutputManifest(file.parent_path(), command);
}

std::string outputManifestState(const std::filesystem::path& dir) {
  const ManifestRecord m = readManifest(normalizedOutputPath(dir));
  return m.valid ? m.state : "";
}

OutputManifestScope::~OutputManifestScope() {
  if (written_) return;
  try {
    std::error_code ec;
    if (std::filesystem::is_directory(dir_, ec)) writeOutputManifest(dir_, command_, "unfinished");
  } catch (const std::exception&) {
    // Already failing: the files written are then unproven, which refuses rather than deletes.
  }
}

void OutputManifestScope::finish(const std::string& state) {
  written_ = true;
  writeOutputManifest(dir_, command_, state);
}

}  // namespace cosim
