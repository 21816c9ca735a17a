#pragma once
// The repeatable `--set key=value` option of the planning commands: parameters by name into a
// ParamSet (the planner's factory then rejects names it does not know).
#include <string>
#include <vector>

#include "core/param_set.h"

namespace cosim::cli {

// Throws InputError naming the option if an entry is not key=value.
void applySetOptions(const std::vector<std::string>& sets, ParamSet& params);

}  // namespace cosim::cli
