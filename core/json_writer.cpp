#include "core/json_writer.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

namespace cosim {

namespace {

using Json = nlohmann::ordered_json;

Json finiteOrNull(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

// Two-space indentation; invalid UTF-8 replaced rather than thrown on (names in a scenario are
// the user's bytes).
std::string dumpText(const Json& j) {
  return j.dump(2, ' ', /*ensure_ascii=*/false, Json::error_handler_t::replace);
}

}  // namespace

JsonObject::JsonObject() : json_(std::make_unique<Json>(Json::object())) {}
JsonObject::JsonObject(const JsonObject& other) : json_(std::make_unique<Json>(*other.json_)) {}
JsonObject::JsonObject(JsonObject&& other) noexcept
    : json_(std::exchange(other.json_, std::make_unique<Json>(Json::object()))) {}
JsonObject& JsonObject::operator=(const JsonObject& other) {
  *json_ = *other.json_;
  return *this;
}
JsonObject& JsonObject::operator=(JsonObject&& other) noexcept {
  std::swap(json_, other.json_);
  return *this;
}
JsonObject::~JsonObject() = default;

JsonObject& JsonObject::set(const std::string& key, Json&& value) {
  (*json_)[key] = std::move(value);
  return *this;
}

JsonObject& JsonObject::add(const std::string& key, double v) {
  return set(key, finiteOrNull(v));
}
JsonObject& JsonObject::add(const std::string& key, int v) {
  return set(key, Json(v));
}
JsonObject& JsonObject::add(const std::string& key, long v) {
  return set(key, Json(v));
}
JsonObject& JsonObject::add(const std::string& key, std::size_t v) {
  return set(key, Json(v));
}
JsonObject& JsonObject::add(const std::string& key, bool v) {
  return set(key, Json(v));
}
JsonObject& JsonObject::add(const std::string& key, const char* v) {
  return set(key, Json(std::string(v)));
}
JsonObject& JsonObject::add(const std::string& key, const std::string& v) {
  return set(key, Json(v));
}
JsonObject& JsonObject::add(const std::string& key, const JsonObject& v) {
  return set(key, Json(*v.json_));
}

JsonObject& JsonObject::add(const std::string& key, const std::map<std::string, double>& m) {
  Json o = Json::object();
  for (const auto& [k, v] : m) o[k] = finiteOrNull(v);
  return set(key, std::move(o));
}

JsonObject& JsonObject::add(const std::string& key, const std::map<std::string, std::string>& m) {
  Json o = Json::object();
  for (const auto& [k, v] : m) o[k] = v;
  return set(key, std::move(o));
}

JsonObject& JsonObject::addArray(const std::string& key, const std::vector<JsonObject>& items) {
  Json a = Json::array();
  for (const JsonObject& item : items) a.push_back(*item.json_);
  return set(key, std::move(a));
}

JsonObject& JsonObject::raw(const std::string& key, const std::string& json) {
  try {
    return set(key, Json::parse(json));
  } catch (const Json::parse_error& e) {
    throw std::invalid_argument("JSON value for \"" + key + "\" is not JSON: " + e.what());
  }
}

std::string JsonObject::str(int indent) const {
  const std::string text = dumpText(*json_);
  if (indent <= 0) return text;
  // Built in place: GCC 12's -Wrestrict misfires on "\n" + std::string(...).
  std::string newline(1 + 2 * static_cast<std::size_t>(indent), ' ');
  newline[0] = '\n';
  std::string shifted;
  shifted.reserve(text.size());
  for (char c : text) {
    if (c == '\n')
      shifted += newline;
    else
      shifted += c;
  }
  return shifted;
}

std::string JsonObject::number(double v) {
  return dumpText(finiteOrNull(v));
}

std::string JsonObject::quote(const std::string& s) {
  return dumpText(Json(s));
}

}  // namespace cosim
