#include "render/log_lookup.h"

#include <algorithm>

#include "sim/flight_metrics.h"

namespace cosim {

std::size_t sampleIndexAt(const VehicleLog& v, double t) {
  auto it = std::upper_bound(v.samples.begin(), v.samples.end(), t,
                             [](double time, const LogSample& s) { return time < s.t; });
  return it == v.samples.begin() ? 0 : static_cast<std::size_t>(it - v.samples.begin() - 1);
}

ErrorReference errorReference(const Scenario& scenario, std::size_t index) {
  bool has_ground = false;
  for (const VehicleSpec& v : scenario.vehicles)
    has_ground = has_ground || v.kind == VehicleKind::GroundRobot;
  if (index < scenario.vehicles.size() && scenario.vehicles[index].kind == VehicleKind::GroundRobot)
    return ErrorReference::TimedPlan;
  if (index < scenario.vehicles.size() && scenario.vehicles[index].reference)
    return ErrorReference::Trajectory;  // a given reference, flown in time
  // With ground robots, the top-level sections are theirs and `aerial` is the quadrotors'.
  const TrajectoryMode mode =
      has_ground ? scenario.aerial.trajectory.mode : scenario.motion.trajectory.mode;
  return mode != TrajectoryMode::Waypoints ? ErrorReference::Trajectory
                                           : ErrorReference::PlannedPath;
}

const char* errorReferenceName(ErrorReference r) {
  switch (r) {
    case ErrorReference::TimedPlan:
      return "timed plan";
    case ErrorReference::Trajectory:
      return "reference trajectory";
    case ErrorReference::PlannedPath:
      return "planned path";
  }
  return "";
}

const char* errorReferenceShortName(ErrorReference r) {
  switch (r) {
    case ErrorReference::TimedPlan:
      return "plan";
    case ErrorReference::Trajectory:
      return "reference";
    case ErrorReference::PlannedPath:
      return "path";
  }
  return "";
}

std::vector<double> trackingErrors(const VehicleLog& v, ErrorReference reference) {
  std::vector<double> e;
  e.reserve(v.samples.size());
  const bool to_path = reference == ErrorReference::PlannedPath && v.planned_path.size() >= 2;
  for (const LogSample& s : v.samples)
    e.push_back(to_path ? distanceToPolyline(s.pos, v.planned_path) : (s.pos - s.ref_pos).norm());
  return e;
}

double logEndTime(const RunLog& log) {
  double t = 0.0;
  for (const auto& v : log.vehicles)
    if (!v.samples.empty()) t = std::max(t, v.samples.back().t);
  return t;
}

}  // namespace cosim
