#pragma once
// One line on what each planner parameter does, for `cosim plan --list`. The defaults and ranges
// are not here: they come from the planners' own declarations (ParamSet::declarations), so they
// cannot drift from what the planners use.
#include <string>

namespace cosim {

// The description of `parameter` as `planner` (single-vehicle or team) reads it; empty if there
// is none (tests/planning/planner_parameters_test checks that every declared parameter has one).
std::string plannerParameterDescription(const std::string& planner, const std::string& parameter);

}  // namespace cosim
