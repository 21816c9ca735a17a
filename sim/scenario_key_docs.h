#pragma once
// docs/scenario_keys.md's "Key by key" tables, made from the settings structs' key declarations
// (sim/declared_keys.h): the page shows exactly these (tests/cli/readme_scenario_keys_test.cpp
// fails when it differs, and rewrites it with COSIM_UPDATE_KEY_DOCS=1).
#include <string>

namespace cosim {

// One Markdown table per declared section: key, type, default, range, meaning.
std::string declaredKeysMarkdown();

}  // namespace cosim
