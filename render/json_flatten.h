#pragma once
// Flattens a JSON document into (dotted key, value text) pairs in document order, e.g.
// {"a": 1, "b": {"c": "x"}, "v": [{"d": true}]} -> a=1, b.c=x, v[0].d=true. Strings lose their
// quotes and escapes. For showing metrics.json as a table.
#include <string>
#include <utility>
#include <vector>

namespace cosim {

// Throws std::runtime_error on malformed JSON.
std::vector<std::pair<std::string, std::string>> flattenJson(const std::string& json);

}  // namespace cosim
