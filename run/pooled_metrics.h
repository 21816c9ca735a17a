#pragma once
// The flight metrics of a group of vehicles taken as one (a team's top-level figures in
// metrics.json): what a researcher reads off a team is the whole team's tracking, not one
// member's. A group of one is that vehicle's metrics, unchanged.
#include <cstddef>
#include <vector>

#include "sim/flight_metrics.h"
#include "sim/run_log.h"

namespace cosim {

// The samples of a vehicle's log its tracking error covers (computeFlightMetrics,
// sim/flight_metrics.h: up to its given reference's end, else its arrival, else the whole run).
std::size_t trackedSamples(const VehicleLog& vehicle);

// Pools each[m] for m in `members` (each[i] computed from log.vehicles[i]):
//   reached_goal: all; collisions: the sum of the members' own counts (a contact between two
//   members is in both);
//   planned_length_m, flown_length_m, energy_proxy: sums; flight_time_s: the longest;
//   rmse_m: the RMS error over every member's tracked samples (trackedSamples);
//   estimation_rmse_m, saturated_fraction: over every member's samples;
//   max_error_m, peak_thrust_fraction, max_speed_mps: the largest; min_clearance_m: the
//   smallest; error_reference: the members' common reference, or Mixed.
// No members: all zero, error_reference None.
FlightMetrics poolFlightMetrics(const std::vector<FlightMetrics>& each, const RunLog& log,
                                const std::vector<std::size_t>& members);

// A quadrotor's longest stretch of continuous mixer saturation in the log, in seconds.
double longestSaturation(const VehicleLog& vehicle);

}  // namespace cosim
