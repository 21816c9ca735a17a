#include "sim/yaml_reader.h"

#include <cmath>
#include <sstream>

#include "core/input_error.h"
#include "core/name_suggestion.h"
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
      const std::string hint = didYouMean(name, allowed);
      fail(kv.first, key.empty() ? name : key + "." + name,
           "unknown key '" + name + "' (" + (hint.empty() ? "" : hint + " ") + "allowed: " + list +
               ")");
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
  if (s.empty() || *end != '\0') fail(node, key, "must be a number, got " + quotedExcerpt(s, 80));
  if (!std::isfinite(v)) fail(node, key, "must be a finite number, got " + quotedExcerpt(s, 80));
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
  if (s.empty() || *end != '\0')
    fail(node, key, "must be a whole number, got " + quotedExcerpt(s, 80));
  if (v < lo || v > hi)
    fail(node, key,
         "= " + s + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

bool YamlReader::boolean(const YAML::Node& node, const std::string& key) const {
  const std::string s = scalar(node, key);
  if (s == "true" || s == "yes" || s == "on") return true;
  if (s == "false" || s == "no" || s == "off") return false;
  fail(node, key, "must be true or false, got " + quotedExcerpt(s, 80));
}

std::string YamlReader::text(const YAML::Node& node, const std::string& key) const {
  const std::string s = scalar(node, key);
  if (s.empty()) fail(node, key, "must not be empty");
  return s;
}

Eigen::Vector3d YamlReader::vec3(const YAML::Node& node, const std::string& key) const {
  if (!node.IsSequence() || node.size() != 3)
    fail(node, key, "must be a list of 3 numbers [x, y, z]");
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = number(node[i], key + "[" + std::to_string(i) + "]");
  return v;
}

namespace {

// One step of an override's path: a mapping key, or (after it, in brackets) a list index.
struct PathStep {
  std::string key;  // empty for an index step
  std::size_t index = 0;
  std::string shown;  // the path up to and including this step, for messages
};

// "vehicles[0].goal" -> vehicles, [0], goal.
std::vector<PathStep> parseOverridePath(const std::string& path, const std::string& assignment) {
  const auto bad = [&](const std::string& problem) {
    return InputError("command line", setAssignmentPlace(assignment), problem);
  };
  // getline yields no empty field after a last '.': "vehicles[0].name." would set name.
  if (!path.empty() && path.back() == '.') throw bad("empty key in path '" + path + "'");
  std::vector<PathStep> steps;
  std::stringstream parts(path);
  std::string shown;
  for (std::string part; std::getline(parts, part, '.');) {
    const std::size_t bracket = part.find('[');
    const std::string key = part.substr(0, bracket);
    if (key.empty()) throw bad("empty key in path '" + path + "'");
    shown += (shown.empty() ? "" : ".") + key;
    steps.push_back({key, 0, shown});
    for (std::size_t at = bracket; at != std::string::npos;) {
      const std::size_t close = part.find(']', at);
      const std::string digits =
          close == std::string::npos ? "" : part.substr(at + 1, close - at - 1);
      if (digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos ||
          (close + 1 < part.size() && part[close + 1] != '['))
        throw bad("'" + part + "': a list element is written name[N], N a whole number from 0");
      // The key must read as the loader's own ("vehicles[0]"), or a later error about the value
      // could not be traced back to this assignment.
      if (digits.size() > 1 && digits[0] == '0')
        throw bad("'" + part + "': write the index without leading zeros (" + shown + "[" +
                  std::to_string(std::stoul(digits)) + "])");
      shown += "[" + digits + "]";
      steps.push_back({"", std::stoul(digits), shown});
      at = close + 1 < part.size() ? close + 1 : std::string::npos;
    }
  }
  if (steps.empty()) throw bad("empty key in path");
  return steps;
}

std::string elementCount(std::size_t n) {
  return n == 1 ? "1 element" : std::to_string(n) + " elements";
}

}  // namespace

std::string overridePathProblem(const std::string& path) {
  try {
    parseOverridePath(path, path);
  } catch (const InputError& e) {
    return e.problem();
  }
  return "";
}

void applyYamlOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("command line", setAssignmentPlace(assignment),
                     "expected key=value, e.g. planner.name=astar");
  const std::string path = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("command line", setAssignmentPlace(path), "value is not valid YAML: " + e.msg);
  }
  try {
    checkYamlStructure(value, "command line");
  } catch (const InputError& e) {
    throw InputError("command line", setAssignmentPlace(assignment), e.problem());
  }
  const std::vector<PathStep> steps = parseOverridePath(path, assignment);
  const auto fail = [&](const std::string& problem) {
    throw InputError("command line", setAssignmentPlace(assignment), problem);
  };
  // Walk the path, creating mappings for missing keys; list elements must exist. yaml-cpp nodes
  // are handles, so reassigning a child handle would rebind rather than write: collect the
  // chain and assign at the end.
  std::vector<YAML::Node> chain{root};
  for (std::size_t i = 0; i < steps.size(); ++i) {
    YAML::Node parent = chain.back();
    const PathStep& step = steps[i];
    const std::string above = i == 0 ? "the document" : steps[i - 1].shown;
    const bool last = i + 1 == steps.size();
    if (!step.key.empty()) {
      if (parent.IsDefined() && !parent.IsNull() && !parent.IsMap())
        fail("'" + step.key + "' is inside " + above + ", which is not a mapping");
      if (last) break;
      YAML::Node child = parent[step.key];
      if (!child.IsDefined() || child.IsNull()) {
        if (steps[i + 1].key.empty())
          fail(step.shown + " is not in the scenario, so it has no element " +
               steps[i + 1].shown.substr(step.shown.size()) + " to set");
        parent[step.key] = YAML::Node(YAML::NodeType::Map);
        child = parent[step.key];
      }
      chain.push_back(child);
      continue;
    }
    if (!parent.IsSequence()) fail(above + " is not a list, so it has no element " + step.shown);
    if (step.index >= parent.size())
      fail("index " + std::to_string(step.index) + " is out of range: " + above + " has " +
           elementCount(parent.size()) +
           (parent.size() ? " (indices 0 to " + std::to_string(parent.size() - 1) + ")" : ""));
    if (last) break;
    chain.push_back(parent[step.index]);
  }
  if (steps.back().key.empty())
    chain.back()[steps.back().index] = value;
  else
    chain.back()[steps.back().key] = value;
}

}  // namespace cosim
