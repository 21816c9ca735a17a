#include "core/output_files.h"

#include <unistd.h>

#include <chrono>
#include <ctime>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_manifest.h"

namespace cosim {

namespace {
constexpr std::size_t kMaxOutputNameBytes = 255;  // NAME_MAX of Linux file systems
}  // namespace

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
  checkNameLengths(dir, "--out");
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

void checkNameLengths(const std::filesystem::path& path, const std::string& option) {
  for (const auto& part : path)
    if (const std::size_t n = part.string().size(); n > kMaxOutputNameBytes)
      throw InputError(path.string(), option,
                       "a name in it is " + std::to_string(n) + " bytes, more than the " +
                           std::to_string(kMaxOutputNameBytes) + " a file system allows");
}

void checkOutputPath(const std::filesystem::path& path, const std::string& option, bool folder) {
  const std::string name = path.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(path.string(), option, "names no file");
  checkNameLengths(path, option);
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
  requireCosimOutput(path, option);
}

void removeStaleResults(const std::filesystem::path& dir, const std::vector<std::string>& names,
                        const std::string& option) {
  const std::vector<std::filesystem::path> doomed = matchingOutputs(dir, names);
  // Every one is checked before any goes: a refusal removes nothing.
  for (const auto& p : doomed) requireCosimOutput(p, option);
  std::error_code ec;
  for (const auto& p : doomed) {
    std::filesystem::remove_all(p, ec);
    if (ec)
      throw InputError(p.string(), option, "cannot remove an earlier result here: " + ec.message());
  }
}

}  // namespace cosim
