#pragma once
// `cosim plan --list`: every planner with its parameters (name, default, valid values, what it
// does), the single-vehicle planners first, then the team (multi-robot) planners.
#include <string>

namespace cosim::cli {

std::string plannerListText();

}  // namespace cosim::cli
