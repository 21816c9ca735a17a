#pragma once
// Reads a scenario section through its settings struct's key declarations (sim/declared_keys.h):
// unknown keys are refused with a did-you-mean, and each key the section gives is checked for
// type and range, its error located "file: line N, key K: problem" (YamlReader) and, for a value
// given with --set, placed at the assignment by the loader (sim/scenario_overrides.h).
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/declared_keys.h"
#include "sim/yaml_reader.h"

namespace cosim {

class DeclaredKeyReader {
 public:
  // Reads the keys `node` gives; `path` ("sim", "aerial.controller") names them in messages.
  DeclaredKeyReader(const YamlReader& r, const YAML::Node& node, std::string path)
      : r_(r), node_(node), path_(std::move(path)) {}

  void number(const char* name, double& field, double lo, double hi, const char*) {
    if (const YAML::Node v = node_[name]) field = r_.number(v, key(name), lo, hi);
  }
  template <class T>
  void integer(const char* name, T& field, long lo, long hi, const char*) {
    if (const YAML::Node v = node_[name]) field = static_cast<T>(r_.integer(v, key(name), lo, hi));
  }
  void boolean(const char* name, bool& field, const char*) {
    if (const YAML::Node v = node_[name]) field = r_.boolean(v, key(name));
  }
  void text(const char* name, std::string& field, const char*) {
    if (const YAML::Node v = node_[name]) field = r_.text(v, key(name));
  }
  void vec3(const char* name, Eigen::Vector3d& field, double lo, double hi, const char*) {
    const YAML::Node v = node_[name];
    if (!v) return;
    field = r_.vec3(v, key(name));
    if (!(field.minCoeff() >= lo && field.maxCoeff() <= hi))
      r_.fail(v, key(name), "each component must be in [" + shown(lo) + ", " + shown(hi) + "]");
  }
  template <class E, class Names>
  void choice(const char* name, E& field, const Names& names, const char*) {
    if (const YAML::Node v = node_[name]) field = oneChoice(v, key(name), names);
  }
  template <class E, class Names>
  void choices(const char* name, std::vector<E>& field, const Names& names, const char*) {
    const YAML::Node v = node_[name];
    if (!v) return;
    if (!v.IsSequence()) r_.fail(v, key(name), "must be a list, each " + choiceList(names));
    for (std::size_t i = 0; i < v.size(); ++i)
      field.push_back(oneChoice(v[i], key(name) + "[" + std::to_string(i) + "]", names));
  }
  void custom(const char*, const char*, const char*) {}

 private:
  std::string key(const char* name) const { return path_ + "." + name; }
  static std::string shown(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
  template <class Names>
  auto oneChoice(const YAML::Node& v, const std::string& where, const Names& names) const {
    const std::string name = r_.text(v, where);
    const auto value = choiceNamed(names, name);
    if (!value) r_.fail(v, where, "must be " + choiceList(names));
    return *value;
  }

  const YamlReader& r_;
  const YAML::Node node_;
  std::string path_;
};

// Checks that `node` (the section at `path`) is a mapping of declared keys only, then reads
// them into `settings`.
template <class Settings>
void readDeclaredKeys(const YamlReader& r, const YAML::Node& node, const std::string& path,
                      Settings& settings) {
  r.checkKeys(node, path, declaredKeyNames(settings));
  DeclaredKeyReader reader(r, node, path);
  settings.declareKeys(reader);
}

}  // namespace cosim
