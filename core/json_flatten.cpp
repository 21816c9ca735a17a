#include "core/json_flatten.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace cosim {

namespace {

using Json = nlohmann::ordered_json;

void flattenInto(const Json& value, const std::string& key, const std::string& null_text,
                 FlatJson& out) {
  if (value.is_object()) {
    for (const auto& [k, v] : value.items())
      flattenInto(v, key.empty() ? k : key + "." + k, null_text, out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      flattenInto(value[i], key + "[" + std::to_string(i) + "]", null_text, out);
  } else if (value.is_string()) {
    out.emplace_back(key, value.get<std::string>());
  } else if (value.is_null()) {
    out.emplace_back(key, null_text);
  } else {
    out.emplace_back(key, value.dump());  // a number or a boolean, as JSON writes it
  }
}

}  // namespace

FlatJson flattenJsonDocument(const Json& document, const std::string& null_text) {
  FlatJson out;
  flattenInto(document, "", null_text, out);
  return out;
}

FlatJson flattenJson(const std::string& json, const std::string& null_text) {
  Json document;
  try {
    document = Json::parse(json);
  } catch (const Json::parse_error& e) {
    throw std::runtime_error(std::string("malformed JSON: ") + e.what());
  }
  return flattenJsonDocument(document, null_text);
}

}  // namespace cosim
