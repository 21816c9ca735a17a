#pragma once
// What `cosim run` prints when a run is done: the figures of metrics.json's top level (for a
// team, the whole team's pooled figures, and it says so), each error named by what it was
// measured against; and a last line naming the pages to open.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace cosim {

// metrics.json's error_reference in words: "trajectory" -> "the reference trajectory",
// "path" -> "the planned path", "timed_plan" -> "the timed plan", "mixed" -> "each vehicle's
// reference"; anything else as it is.
std::string errorReferenceWords(const std::string& reference);

// One line (no newline) from metrics.json's top level: reached_goal, collisions, flight_time_s,
// rmse_m, max_error_m, min_clearance_m, sim_speed_x, error_reference. With more than one
// vehicle (metrics.json's vehicles list) it begins "team of N (pooled):".
std::string runSummaryLine(const nlohmann::ordered_json& metrics);

// "open DIR/index.html" and, when the folder has one, " or DIR/viewer.html"; "results in DIR"
// when the folder has no index.html (--no-images).
std::string runPagesLine(const std::filesystem::path& dir);

}  // namespace cosim
