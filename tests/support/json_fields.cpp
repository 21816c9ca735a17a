#include "tests/support/json_fields.h"

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/json_reading.h"

namespace cosim::test {

namespace {

// The value `part` ("name" or "name[N]") names in `value`; throws naming `key` (and the keys
// there are) if it is absent.
nlohmann::ordered_json step(const nlohmann::ordered_json& value, const std::string& part,
                            const std::string& key) {
  const std::size_t bracket = part.find('[');
  const std::string name = part.substr(0, bracket);
  if (!value.is_object())
    throw std::runtime_error("no key \"" + key + "\": not a JSON object where \"" + name +
                             "\" would be");
  const auto at = value.find(name);
  if (at == value.end()) {
    std::string keys;
    for (const auto& [k, v] : value.items()) keys += (keys.empty() ? "" : ", ") + k;
    throw std::runtime_error("no key \"" + key + "\" in the JSON object (\"" + name +
                             "\" is not among: " + keys + ")");
  }
  if (bracket == std::string::npos) return *at;
  const std::size_t index = std::stoul(part.substr(bracket + 1));
  if (!at->is_array() || index >= at->size())
    throw std::runtime_error("no key \"" + key + "\": \"" + name + "\" has no element " +
                             std::to_string(index));
  return (*at)[index];
}

// The value at `key` of the object `json` holds: a top-level key, or a path through nested
// objects and lists such as "planner_counters.conflicts" or "rows[0].length_m".
nlohmann::ordered_json field(const std::string& json, const std::string& key) {
  nlohmann::ordered_json value = parseJsonText(json, "the JSON under test");
  for (std::size_t from = 0;;) {
    const std::size_t dot = key.find('.', from);
    nlohmann::ordered_json inner =
        step(value, key.substr(from, dot == std::string::npos ? dot : dot - from), key);
    value = std::move(inner);
    if (dot == std::string::npos) return value;
    from = dot + 1;
  }
}

}  // namespace

double jsonNumber(const std::string& json, const std::string& key) {
  const nlohmann::ordered_json value = field(json, key);
  if (!value.is_number())
    throw std::runtime_error("key \"" + key + "\" holds " + value.dump() + ", not a number");
  return value.get<double>();
}

bool jsonTrue(const std::string& json, const std::string& key) {
  const nlohmann::ordered_json value = field(json, key);
  if (!value.is_boolean())
    throw std::runtime_error("key \"" + key + "\" holds " + value.dump() + ", not true or false");
  return value.get<bool>();
}

}  // namespace cosim::test
