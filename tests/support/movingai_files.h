#pragma once
// The MovingAI benchmark files the tests read, each kept once in the repository: the maps and
// scenario files cosim bundles in experiments/maps/ (attribution in its README.md), and in
// tests/data/movingai/ only those no bundled scenario needs (the grid tests' city, game and
// even-scenario files).
#include <string>

namespace cosim::test {

// The path of the MovingAI file `name` (e.g. "random-32-32-10.map"): experiments/maps/NAME if it
// is there, else tests/data/movingai/NAME (where a missing file is then reported by its reader).
std::string movingAIFile(const std::string& name);

}  // namespace cosim::test
