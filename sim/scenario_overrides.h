#pragma once
// Where the loader places an error in a value given with --set (part of sim/scenario_loader.cpp).
// Values given with --set come from the command line, not from a line of the file (YAML parses
// each one as a document of its own, so its nodes say "line 1"): their errors are placed at the
// assignment, "--set planner.resolution=fast, key planner.resolution". The key stays in the
// place, where sweeps look for it.
#include <string>
#include <vector>

#include "core/input_error.h"

namespace cosim {

// The --set assignment behind `key`: the last one naming the key or a mapping above it (it
// replaced everything below), or, if the key has no line in the file (`created`), the one whose
// path made it. Empty if the file gave the key.
std::string overrideBehind(const std::vector<std::string>& overrides, const std::string& key,
                           bool created);

// "--set ASSIGNMENT, key KEY": the place of an error in a value the assignment gave.
std::string overridePlace(const std::string& assignment, const std::string& key);

// `e` placed at the --set assignment behind its key, if there is one. YamlReader's places are
// "line N, key K", or "key K" for a node an assignment created (it has no position).
InputError placedAtOverride(const InputError& e, const std::string& file,
                            const std::vector<std::string>& overrides);

}  // namespace cosim
