#include "core/output_files.h"

#include <unistd.h>

#include <chrono>
#include <ctime>

#include "core/atomic_file.h"
#include "core/input_error.h"

namespace cosim {

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

void checkOutputDir(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::path existing = std::filesystem::absolute(dir, ec);
  while (!existing.empty() && !std::filesystem::exists(existing, ec) &&
         existing != existing.parent_path())
    existing = existing.parent_path();
  if (!std::filesystem::is_directory(existing, ec))
    throw InputError(dir, "--out", "cannot create folder: Not a directory");
  if (::access(existing.c_str(), W_OK) != 0)
    throw InputError(dir, "--out",
                     std::filesystem::path(dir) == existing
                         ? "folder is not writable"
                         : "cannot create folder: Permission denied");
}

void checkOutputPath(const std::filesystem::path& path, const std::string& option, bool folder) {
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(path.string(), option, "names no file");
  if (name.size() > 255)
    throw InputError(path.string(), option,
                     "the name is " + std::to_string(name.size()) +
                         " bytes, more than the 255 a file system allows");
  std::error_code ec;
  if (!folder && std::filesystem::is_directory(path, ec))
    throw InputError(path.string(), option, "is a folder; give a file name");
  if (const std::string kind = specialFileKind(path); !kind.empty())
    throw InputError(path.string(), option, notRegularProblem(kind));
  if (folder && std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec))
    throw InputError(path.string(), option, "exists and is not a folder");
  const std::filesystem::path parent =
      path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  if (!std::filesystem::exists(parent, ec))
    throw InputError(path.string(), option, "folder " + parent.string() + " does not exist");
  if (!std::filesystem::is_directory(parent, ec))
    throw InputError(path.string(), option, parent.string() + " is not a folder");
  if (::access(parent.c_str(), W_OK) != 0)
    throw InputError(path.string(), option, "folder " + parent.string() + " is not writable");
}

void removeStaleResults(const std::filesystem::path& dir, const std::vector<std::string>& names) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return;
  std::vector<std::filesystem::path> doomed;
  for (const std::string& n : names) {
    if (n.empty() || n.back() != '*') {
      doomed.push_back(dir / n);
      continue;
    }
    const std::string prefix = n.substr(0, n.size() - 1);
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
      if (e.path().filename().string().rfind(prefix, 0) == 0) doomed.push_back(e.path());
  }
  for (const auto& p : doomed) {
    std::filesystem::remove_all(p, ec);
    if (ec)
      throw InputError(p.string(), "--out",
                       "cannot remove an earlier result here: " + ec.message());
  }
}

}  // namespace cosim
