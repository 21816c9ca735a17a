#pragma once
// What `cosim run` prints when a run is done: the record's top-level figures, those metrics.json
// has at its top level (for a team, the whole team's pooled figures, and it says so), each error
// named by what it was measured against; and a last line naming the pages to open.
#include <filesystem>
#include <string>

#include "run/record/run_record.h"

namespace cosim {

// An error reference in words: "the reference trajectory", "the planned path", "the timed
// plan", "each vehicle's reference" (a pool of vehicles measured against different ones).
std::string errorReferenceWords(ErrorReference reference);

// One line (no newline) from the record: reached_goal, collisions, flight time, rmse, max error,
// min clearance (of the pooled top-level vehicles) and the simulation speed. With more than one
// vehicle it begins "team of N (pooled):"; a run of robots with quadrotors gives both groups.
std::string runSummaryLine(const RunRecord& record);

// "open DIR/index.html" and, when the folder has one, " or DIR/viewer.html"; "results in DIR"
// when the folder has no index.html (--no-images).
std::string runPagesLine(const std::filesystem::path& dir);

}  // namespace cosim
