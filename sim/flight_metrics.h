#pragma once
// Evaluation of a flight, computed from the run log and the world's geometry alone.
#include <string>

#include "planning/world/world.h"
#include "sim/run_log.h"

namespace cosim {

struct FlightMetrics {
  bool reached_goal = false;
  int collisions = 0;
  double planned_length_m = 0.0;
  double flown_length_m = 0.0;
  double flight_time_s = 0.0;     // to arrival, or the whole run if the goal was not reached
  // Position error: against the reference trajectory (trajectory modes), or, when the
  // reference jumps between waypoints (seed 003's mode), the distance to the planned path.
  std::string error_reference;    // "trajectory" or "path"
  double rmse_m = 0.0;
  double max_error_m = 0.0;
  double min_clearance_m = 0.0;   // vehicle bounding sphere to the nearest obstacle surface
  double peak_thrust_fraction = 0.0;  // max rotor thrust / rotor limit
  double saturated_fraction = 0.0;    // share of control steps with mixer saturation
  double energy_proxy = 0.0;      // integral of sum_i thrust_i^1.5 dt (induced power ~ T^1.5)
  double max_speed_mps = 0.0;
  // The estimator's 3D position error against the truth, RMS over the whole run (0 with ideal
  // sensing: the controller saw the truth).
  double estimation_rmse_m = 0.0;
};

// Until when a vehicle's tracking error is taken: the end of its given reference
// (VehicleLog::reference_end), else its arrival, else the end of its log.
double trackingEnd(const VehicleLog& log);

// error_against_trajectory: true when the reference is a time-parametrised trajectory.
FlightMetrics computeFlightMetrics(const VehicleLog& log, const World& world,
                                   bool error_against_trajectory);

// Shortest distance from p to a polyline.
double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& polyline);

}  // namespace cosim
