#pragma once
// Flattens a JSON document into (key path, value text) pairs in document order, e.g.
// {"a": 1, "b": {"c": "x"}, "v": [{"d": true}]} -> a=1, b.c=x, v[0].d=true: how metrics.json is
// shown as a table (the HTML report) and becomes columns (a sweep's results.csv). Strings lose
// their quotes and escapes; numbers are written as JSON writes them (shortest round-trip form);
// booleans as true/false; null as `null_text`; empty objects and arrays give no pair.
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

namespace cosim {

using FlatJson = std::vector<std::pair<std::string, std::string>>;

FlatJson flattenJsonDocument(const nlohmann::ordered_json& document,
                             const std::string& null_text = "null");

// The same from JSON text; throws std::runtime_error on malformed JSON.
FlatJson flattenJson(const std::string& json, const std::string& null_text = "null");

}  // namespace cosim
