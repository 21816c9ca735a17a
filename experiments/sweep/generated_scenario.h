#pragma once
// Turns a sweep file's world generator entry into a scenario file: the generated world plus a
// quad_1500g flying from its start to its goal with A* (0.5 m cells), a minimum-snap trajectory
// at up to 3 m/s and the geometric controller. Any of these keys can then be varied like in a
// hand-written scenario.
#include <string>

#include "experiments/sweep/sweep_spec.h"

namespace cosim {

// The scenario YAML for one (density, seed) of a generator entry. Throws InputError (naming the
// entry) if the generator rejects its options.
std::string generatedScenarioYaml(const GeneratorSpec& g, double density, long seed,
                                  const std::string& sweep_file);

// A file name for it: "<type>-d<density>-s<seed>.yaml" (plus the size when it is not the default).
std::string generatedScenarioName(const GeneratorSpec& g, double density, long seed);

}  // namespace cosim
