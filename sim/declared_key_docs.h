#pragma once
// The documentation of a scenario section, from its settings struct's key declarations
// (sim/declared_keys.h): one row per key with its type, default (the value a fresh struct holds),
// range and line of doc, as docs/scenario_keys.md shows them (sim/scenario_key_docs.h).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "sim/declared_keys.h"

namespace cosim {

struct DeclaredKeyRow {
  std::string name, type, default_value, range, doc;
};

class DeclaredKeyDocs {
 public:
  const std::vector<DeclaredKeyRow>& rows() const { return rows_; }

  void number(const char* name, double& field, double lo, double hi, const char* doc) {
    rows_.push_back({name, "number", shown(field), range(lo, hi), doc});
  }
  template <class T>
  void integer(const char* name, T& field, long lo, long hi, const char* doc) {
    rows_.push_back({name, "whole number", std::to_string(field),
                     range(static_cast<double>(lo), static_cast<double>(hi)), doc});
  }
  void boolean(const char* name, bool& field, const char* doc) {
    rows_.push_back({name, "true/false", field ? "true" : "false", "", doc});
  }
  void text(const char* name, std::string& field, const char* doc) {
    rows_.push_back({name, "name", field.empty() ? "(none)" : field, "", doc});
  }
  void vec3(const char* name, Eigen::Vector3d& field, double lo, double hi, const char* doc) {
    std::string value;
    value.append("[").append(shown(field.x())).append(", ").append(shown(field.y()));
    value.append(", ").append(shown(field.z())).append("]");
    std::string each = range(lo, hi);
    if (!each.empty()) each.insert(0, "each in ");
    rows_.push_back({name, "[x, y, z]", value, each, doc});
  }
  template <class E, class Names>
  void choice(const char* name, E& field, const Names& names, const char* doc) {
    rows_.push_back({name, "choice", choiceName(names, field), nameList(names), doc});
  }
  template <class E, class Names>
  void choices(const char* name, std::vector<E>& field, const Names& names, const char* doc) {
    std::string value;
    for (const E& e : field) value += std::string(value.empty() ? "" : ", ") + choiceName(names, e);
    rows_.push_back({name, "list of choices", "[" + value + "]", nameList(names), doc});
  }
  void custom(const char* name, const char* type, const char* doc) {
    rows_.push_back({name, type, "", "", doc});
  }

 private:
  // Whole numbers below a million as such, others in the shortest text that reads back as the
  // same double.
  static std::string shown(double v) {
    char buf[32];
    if (v == std::floor(v) && std::abs(v) < 1e6) {
      std::snprintf(buf, sizeof buf, "%.0f", v);
      return buf;
    }
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(buf, sizeof buf, "%.*g", digits, v);
      if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
  }
  // Unbounded sides (the reader's +-1e300) are left open. Appended piece by piece: GCC 12 warns
  // falsely (-Wstringop-overflow) on a chain of string concatenations inlined here.
  static std::string range(double lo, double hi) {
    std::string out;
    if (lo <= -1e299 && hi >= 1e299) return out;
    if (hi >= 1e299) {
      out.append(">= ").append(shown(lo));
    } else if (lo <= -1e299) {
      out.append("<= ").append(shown(hi));
    } else {
      out.append("[").append(shown(lo)).append(", ").append(shown(hi)).append("]");
    }
    return out;
  }
  template <class Names>
  static std::string nameList(const Names& names) {
    std::string list;
    for (const auto& c : names) list += std::string(list.empty() ? "" : ", ") + "`" + c.name + "`";
    return list;
  }

  std::vector<DeclaredKeyRow> rows_;
};

// The rows of `settings`' declared keys, its current values as the defaults.
template <class Settings>
std::vector<DeclaredKeyRow> declaredKeyRows(Settings settings) {
  DeclaredKeyDocs docs;
  settings.declareKeys(docs);
  return docs.rows();
}

}  // namespace cosim
