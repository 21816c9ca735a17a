#include "sim/yaml_reader.h"

#include <cmath>
#include <sstream>

#include "planning/input_error.h"
#include "sim/yaml_document.h"

namespace cosim {

std::string YamlReader::place(const YAML::Node& node, const std::string& key) const {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null() || mark.line < 0) return "key " + key;
  return "line " + std::to_string(mark.line + 1) + ", key " + key;
}

void YamlReader::fail(const YAML::Node& node, const std::string& key,
                      const std::string& problem) const {
  throw InputError(file_, place(node, key), problem);
}

void YamlReader::requireMap(const YAML::Node& node, const std::string& key) const {
  if (!node.IsMap()) fail(node, key, "must be a mapping (key: value pairs)");
}

void YamlReader::checkKeys(const YAML::Node& node, const std::string& key,
                           const std::vector<std::string>& allowed) const {
  requireMap(node, key);
  for (const auto& kv : node) {
    const std::string name = kv.first.Scalar();
    bool known = false;
    for (const auto& a : allowed) known = known || (a == name);
    if (!known) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      fail(kv.first, key.empty() ? name : key + "." + name,
           "unknown key '" + name + "' (allowed: " + list + ")");
    }
  }
}

std::string YamlReader::scalar(const YAML::Node& node, const std::string& key) const {
  if (!node.IsScalar()) fail(node, key, "must be a single value");
  return node.Scalar();
}

double YamlReader::number(const YAML::Node& node, const std::string& key, double lo,
                          double hi) const {
  const std::string s = scalar(node, key);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0') fail(node, key, "must be a number, got '" + s + "'");
  if (!std::isfinite(v)) fail(node, key, "must be a finite number, got '" + s + "'");
  if (v < lo || v > hi) {
    std::ostringstream msg;
    msg << "= " << v << " is outside [" << lo << ", " << hi << "]";
    fail(node, key, msg.str());
  }
  return v;
}

long YamlReader::integer(const YAML::Node& node, const std::string& key, long lo, long hi) const {
  const std::string s = scalar(node, key);
  char* end = nullptr;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0') fail(node, key, "must be a whole number, got '" + s + "'");
  if (v < lo || v > hi)
    fail(node, key,
         "= " + s + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& key) const {
  const std::string s = scalar(node, key);
  if (s == "true" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "no" || s == "off") return false;
  fail(node, key, "must be true or false, got '" + s + "'");
}

std::string YamlReader::text(const YAML::Node& node, const std::string& key) const {
  const std::string s = scalar(node, key);
  if (s.empty()) fail(node, key, "must not be empty");
  return s;
}

Eigen::Vector3d YamlReader::vec3(const YAML::Node& node, const std::string& key) const {
  if (!node.IsSequence() || node.size() != 3) fail(node, key, "must be a list of 3 numbers [x, y, z]");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = number(node[i], key + "[" + std::to_string(i) + "]");
  return v;
}

void applyYamlOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("command line", "--set " + assignment, "expected key=value, e.g. planner.name=astar");
  const std::string path = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("command line", "--set " + path, "value is not valid YAML: " + e.msg);
  }
  try {
    checkYamlStructure(value, "command line");
  } catch (const InputError& e) {
    throw InputError("command line", "--set " + assignment, e.problem());
  }
  // Walk the dotted path, creating mappings; yaml-cpp nodes are handles, so reassigning a child
  // handle would rebind rather than write: collect the chain and assign at the end.
  std::vector<std::string> keys;
  std::stringstream ss(path);
  for (std::string k; std::getline(ss, k, '.');) {
    if (k.empty()) throw InputError("command line", "--set " + path, "empty key in path");
    keys.push_back(k);
  }
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    YAML::Node parent = chain.back();
    if (parent.IsDefined() && !parent.IsNull() && !parent.IsMap())
      throw InputError("command line", "--set " + path, "'" + keys[i] + "' is inside a non-mapping");
    YAML::Node child = parent[keys[i]];
    if (!child.IsDefined() || child.IsNull()) {
      parent[keys[i]] = YAML::Node(YAML::NodeType::Map);
      child = parent[keys[i]];
    }
    chain.push_back(child);
  }
  chain.back()[keys.back()] = value;
}

}  // namespace cosim
