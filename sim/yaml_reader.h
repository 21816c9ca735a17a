#pragma once
// Strict, located reading of YAML documents: every value is checked for type and range, every
// mapping for unknown keys, and every error names the file, the line and the key path.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cosim {

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  // "line 12, key planner.name" (or "key planner.name" when the node has no position, e.g. it
  // came from --set).
  std::string place(const YAML::Node& node, const std::string& key) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& key,
                         const std::string& problem) const;

  void requireMap(const YAML::Node& node, const std::string& key) const;
  // Throws for the first key of `node` not in `allowed`.
  void checkKeys(const YAML::Node& node, const std::string& key,
                 const std::vector<std::string>& allowed) const;

  double number(const YAML::Node& node, const std::string& key, double lo = -1e300,
                double hi = 1e300) const;
  long integer(const YAML::Node& node, const std::string& key, long lo, long hi) const;
  bool boolean(const YAML::Node& node, const std::string& key) const;
  std::string text(const YAML::Node& node, const std::string& key) const;
  Eigen::Vector3d vec3(const YAML::Node& node, const std::string& key) const;
  // A scalar as written (for parameters handed on to a ParamSet).
  std::string scalar(const YAML::Node& node, const std::string& key) const;

 private:
  std::string file_;
};

// Applies "a.b.c=value" to a YAML tree (creating maps as needed; value parsed as YAML).
// Throws InputError naming the override if it is malformed.
void applyYamlOverride(YAML::Node& root, const std::string& assignment);

// Why `path` cannot be the key of an override ("a.b", "vehicles[0].goal"), or "" if it can:
// the same rules applyYamlOverride applies, for keys checked before any scenario is read (a
// sweep's `vary:`).
std::string overridePathProblem(const std::string& path);

}  // namespace cosim
