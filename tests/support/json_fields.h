#pragma once
// Fields of a JSON object that cosim wrote (metrics.json, mapf.json, a comparison's JSON), read
// with the project's own JSON reader (core/json_reading.h). `key` is a top-level key, or a path
// through nested objects and lists such as "planner_counters.conflicts" or "rows[0].length_m".
// A key that is missing, or holds another type, throws std::runtime_error naming the key, so the
// test fails: a renamed key must not read as a number that every bound passes.
#include <string>

namespace cosim::test {

// The number at `key`; throws if `json` is not a JSON object or `key` is not a number in it.
double jsonNumber(const std::string& json, const std::string& key);

// The boolean at `key`; throws if `json` is not a JSON object or `key` is not a boolean in it.
bool jsonTrue(const std::string& json, const std::string& key);

}  // namespace cosim::test
