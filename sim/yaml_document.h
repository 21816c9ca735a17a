#pragma once
// YAML documents read safely. yaml-cpp accepts things that break every later reader: an alias
// inside its own anchor (`set: &s {a: *s}`) makes a cycle that any walk of the tree follows
// forever; aliases of aliases multiply a small file into millions of values; a key given twice
// keeps one of its values and drops the other silently. Every document cosim reads passes these
// checks first, so the readers after them see a finite tree of known size with unique keys.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace cosim {

// Deeper than any scenario or sweep file needs (they nest 5 levels), shallow enough that every
// recursive walk of the tree (yaml-cpp's emitter, flatteners) stays far from the stack's end.
constexpr int kMaxYamlDepth = 64;
// Values after alias expansion (an alias counts once per use), keys included. yaml-cpp spends
// about 470 bytes per value, so this bounds a document at about 470 MB; the loader's largest
// world (10 000 obstacles) has about 130 000.
constexpr std::size_t kMaxYamlValues = 1000000;

// Parses one document (empty text: a null node), counting its values before building any.
// Throws InputError(file, "line N", ...) for malformed YAML, more than kMaxYamlValues values, and
// what checkYamlStructure refuses.
YAML::Node loadYamlDocument(const std::string& text, const std::string& file);

// Throws InputError(file, "line N, key a.b[2]", problem) for a cycle of aliases, nesting deeper
// than kMaxYamlDepth, more than kMaxYamlValues values after alias expansion, a key that is not
// a plain scalar, or a key given twice in one mapping. Walks the tree without recursion.
void checkYamlStructure(const YAML::Node& root, const std::string& file);

}  // namespace cosim
