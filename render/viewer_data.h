#pragma once
// What a run's viewer.html replays, as one JSON document: the world's shapes (render/
// scene_shapes.h), each vehicle's shape, planned path and goal, the moments worth a marker
// (render/run_moments.h), and the log resampled on a common frame clock and packed as little-
// endian 16-bit integers in base64 (positions quantised to about a millimetre, tracking errors in
// mm, attitudes as unit quaternions times 32767, velocities in cm/s, rotor thrusts as fractions
// of the rotor limit).
#include <nlohmann/json.hpp>

#include "run/record/run_record.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// Frames per second of the replay: 30, lowered for large teams so that vehicles x frames stays
// within kViewerSampleBudget (a 1000-robot execution still loads in a browser), never below 2.
constexpr double kViewerMaxRate = 30.0;
constexpr double kViewerMinRate = 2.0;
constexpr double kViewerSampleBudget = 400000.0;
double viewerFrameRate(std::size_t vehicles, double duration);

// title: shown in the page's corner; status: one line under it (e.g. the run's outcome).
// record: the run's record, for each vehicle's tracking errors, error reference and controller;
// without one (a hand-made log) the error is the distance to the logged reference.
// The colours come from render/overlay_palette.h (visualLanguageJson, as "style").
nlohmann::json viewerData(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                          const std::string& title, const std::string& status,
                          const RunRecord* record = nullptr);

}  // namespace cosim
