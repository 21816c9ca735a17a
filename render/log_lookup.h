#pragma once
// Looking things up in a run log by time, and the tracking error the renderer and the figures
// colour by (the same definition as each vehicle's metrics in metrics.json).
#include <cstddef>
#include <string>
#include <vector>

#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim {

// Index of the last sample at or before t (0 if t precedes the first); samples are in time order.
std::size_t sampleIndexAt(const VehicleLog& v, double t);

// What a vehicle's tracking error is measured against, as its metrics measure it: a ground
// robot against its timed plan (the plan-vs-executed deviation), a quadrotor against its
// reference trajectory when it flies a time-parametrised one, else against its planned path
// (a waypoint reference jumps between waypoints, so the distance to it says nothing).
enum class ErrorReference { TimedPlan, Trajectory, PlannedPath };

// The reference of vehicle `index` of the scenario (a quadrotor beside ground robots follows
// the `aerial` trajectory mode). A log vehicle the scenario does not list (hand-made logs in
// tests) is taken as a quadrotor of the top-level trajectory mode.
ErrorReference errorReference(const Scenario& scenario, std::size_t index);
// "timed plan", "reference trajectory", "planned path"; short: "plan", "reference", "path".
const char* errorReferenceName(ErrorReference r);
const char* errorReferenceShortName(ErrorReference r);

// Position error of every sample against `reference`.
std::vector<double> trackingErrors(const VehicleLog& v, ErrorReference reference);

// The time of the last sample over all vehicles.
double logEndTime(const RunLog& log);

}  // namespace cosim
