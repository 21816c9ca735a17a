#pragma once
// A small writer for flat JSON objects (metrics.json, plan.json, ...): keys keep the order in
// which they were added, numbers are written with enough digits to round-trip, and non-finite
// numbers become null (JSON has no NaN).
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace cosim {

class JsonObject {
 public:
  JsonObject& add(const std::string& key, double v) { return raw(key, number(v)); }
  JsonObject& add(const std::string& key, int v) { return raw(key, std::to_string(v)); }
  JsonObject& add(const std::string& key, long v) { return raw(key, std::to_string(v)); }
  JsonObject& add(const std::string& key, std::size_t v) { return raw(key, std::to_string(v)); }
  JsonObject& add(const std::string& key, bool v) { return raw(key, v ? "true" : "false"); }
  JsonObject& add(const std::string& key, const char* v) { return raw(key, quote(v)); }
  JsonObject& add(const std::string& key, const std::string& v) { return raw(key, quote(v)); }
  JsonObject& add(const std::string& key, const JsonObject& v) { return raw(key, v.str(1)); }
  JsonObject& add(const std::string& key, const std::map<std::string, double>& m) {
    JsonObject o;
    for (const auto& [k, v] : m) o.add(k, v);
    return raw(key, o.str(1));
  }
  JsonObject& add(const std::string& key, const std::map<std::string, std::string>& m) {
    JsonObject o;
    for (const auto& [k, v] : m) o.add(k, v);
    return raw(key, o.str(1));
  }
  JsonObject& addArray(const std::string& key, const std::vector<JsonObject>& items) {
    std::string s = "[";
    for (std::size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + items[i].str(2);
    return raw(key, s + "]");
  }
  JsonObject& raw(const std::string& key, const std::string& json) {
    fields_.emplace_back(key, json);
    return *this;
  }

  std::string str(int indent = 0) const {
    const std::string pad(2 * (indent + 1), ' '), end_pad(2 * indent, ' ');
    std::string s = "{\n";
    for (std::size_t i = 0; i < fields_.size(); ++i)
      s += pad + quote(fields_[i].first) + ": " + fields_[i].second +
           (i + 1 < fields_.size() ? ",\n" : "\n");
    return s + end_pad + "}";
  }

  static std::string number(double v) {
    if (!std::isfinite(v)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
  }
  static std::string quote(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
      switch (c) {
        case '"': q += "\\\""; break;
        case '\\': q += "\\\\"; break;
        case '\n': q += "\\n"; break;
        case '\t': q += "\\t"; break;
        default:
          if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            q += buf;
          } else {
            q += c;
          }
      }
    }
    return q + "\"";
  }

 private:
  std::vector<std::pair<std::string, std::string>> fields_;
};

}  // namespace cosim
