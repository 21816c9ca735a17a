#pragma once
// Evaluation of a flight, computed from the run log and the world's geometry alone.
#include <vector>

#include "planning/world/world.h"
#include "sim/error_reference.h"
#include "sim/run_log.h"

namespace cosim {

struct FlightMetrics {
  bool reached_goal = false;
  int collisions = 0;
  double planned_length_m = 0.0;
  double flown_length_m = 0.0;
  double flight_time_s = 0.0;  // to arrival, or the whole run if the goal was not reached
  // Position error: against the timed plan (a ground robot), the reference trajectory
  // (trajectory modes, given references), or, when the reference jumps between waypoints (seed
  // 003's mode), the distance to the planned path.
  ErrorReference error_reference = ErrorReference::PlannedPath;
  double rmse_m = 0.0;
  double max_error_m = 0.0;
  double min_clearance_m = 0.0;       // vehicle bounding sphere to the nearest obstacle surface
  double peak_thrust_fraction = 0.0;  // max rotor thrust / rotor limit
  double saturated_fraction = 0.0;    // share of control steps with mixer saturation
  double energy_proxy = 0.0;          // integral of sum_i thrust_i^1.5 dt (induced power ~ T^1.5)
  double max_speed_mps = 0.0;
  // The estimator's 3D position error against the truth, RMS over the whole run (0 with ideal
  // sensing: the controller saw the truth).
  double estimation_rmse_m = 0.0;
};

// Until when a vehicle's tracking error is taken: the end of its given reference
// (VehicleLog::reference_end), else its arrival, else the end of its log.
double trackingEnd(const VehicleLog& log);

// `reference`: what the position error is measured against (PlannedPath: the distance to the
// planned path; any other: the distance to the logged reference position).
FlightMetrics computeFlightMetrics(const VehicleLog& log, const World& world,
                                   ErrorReference reference);

// Position error of every sample against `reference`, as the pictures colour by it (a path of
// fewer than two points falls back to the logged reference position).
std::vector<double> trackingErrors(const VehicleLog& log, ErrorReference reference);

// Shortest distance from p to a polyline.
double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& polyline);

}  // namespace cosim
