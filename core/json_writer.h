#pragma once
// The JSON objects cosim writes (metrics.json, plan.json, result.json, ...), built key by key on
// nlohmann::ordered_json: keys keep the order in which they were added, doubles are written in
// the shortest form that reads back to the same double, and non-finite numbers become null (JSON
// has no NaN). The document is held behind a pointer so that this header, included widely, does
// not pull in all of nlohmann/json.hpp; include that to use json().
#include <cstddef>
#include <map>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace cosim {

class JsonObject {
 public:
  JsonObject();
  JsonObject(const JsonObject& other);
  JsonObject(JsonObject&& other) noexcept;
  JsonObject& operator=(const JsonObject& other);
  JsonObject& operator=(JsonObject&& other) noexcept;
  ~JsonObject();

  // Adding a key that is already there replaces its value in place.
  JsonObject& add(const std::string& key, double v);
  JsonObject& add(const std::string& key, int v);
  JsonObject& add(const std::string& key, long v);
  JsonObject& add(const std::string& key, std::size_t v);
  JsonObject& add(const std::string& key, bool v);
  JsonObject& add(const std::string& key, const char* v);
  JsonObject& add(const std::string& key, const std::string& v);
  JsonObject& add(const std::string& key, const JsonObject& v);
  JsonObject& add(const std::string& key, const std::map<std::string, double>& m);
  JsonObject& add(const std::string& key, const std::map<std::string, std::string>& m);
  JsonObject& addArray(const std::string& key, const std::vector<JsonObject>& items);
  // `json` is JSON text (any value); it is parsed, and std::invalid_argument naming the key is
  // thrown if it is not JSON.
  JsonObject& raw(const std::string& key, const std::string& json);

  // The object as text, two spaces per level. `indent` is the nesting level at which the text is
  // placed: every line after the first is shifted by 2 * indent spaces. Strings that are not
  // valid UTF-8 have the bad bytes replaced by U+FFFD, so the text is always valid JSON.
  std::string str(int indent = 0) const;
  const nlohmann::ordered_json& json() const { return *json_; }

  // A double as str() writes it ("null" if not finite), e.g. for a CSV cell beside the JSON.
  static std::string number(double v);
  // A string as a JSON string literal, quotes and escapes included.
  static std::string quote(const std::string& s);

 private:
  JsonObject& set(const std::string& key, nlohmann::ordered_json&& value);

  std::unique_ptr<nlohmann::ordered_json> json_;
};

}  // namespace cosim
