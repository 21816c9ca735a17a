#pragma once
// `cosim mapf` on one instance: the first N agents of one scenario file, one planner. Writes
// DIR/mapf.json and DIR/paths.csv; the plan is checked by the independent SolutionValidator.
// With --execute, ground robots then drive it in MuJoCo (mapf_execution.h).
#include "cli/mapf_options.h"

namespace cosim::cli {

// Returns the exit status: 0 a conflict-free solution (and, with --execute, a run that reached
// its goals), 1 planning or execution failed or was interrupted. Throws InputError on bad input.
int runSingleMapf(const MapfArgs& args, int agents);

}  // namespace cosim::cli
