#include "sim/flight_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/world/segment_distance.h"

namespace cosim {

double distanceToPolyline(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& line) {
  if (line.empty()) return std::numeric_limits<double>::infinity();
  double best = (p - line[0]).norm();
  for (std::size_t i = 1; i < line.size(); ++i) {
    best = std::min(best, distanceToSegment(p, line[i - 1], line[i]));
  }
  return best;
}

double trackingEnd(const VehicleLog& log) {
  if (log.reference_end >= 0.0) return log.reference_end + 1e-9;  // the sample at the end too
  if (log.reached_goal) return log.arrival_time;
  return log.samples.empty() ? 0.0 : log.samples.back().t;
}

std::vector<double> trackingErrors(const VehicleLog& v, ErrorReference reference) {
  std::vector<double> e;
  e.reserve(v.samples.size());
  const bool to_path = reference == ErrorReference::PlannedPath && v.planned_path.size() >= 2;
  for (const LogSample& s : v.samples)
    e.push_back(to_path ? distanceToPolyline(s.pos, v.planned_path) : (s.pos - s.ref_pos).norm());
  return e;
}

FlightMetrics computeFlightMetrics(const VehicleLog& log, const World& world,
                                   ErrorReference reference) {
  const bool error_against_trajectory = reference != ErrorReference::PlannedPath;
  FlightMetrics m;
  m.reached_goal = log.reached_goal;
  m.collisions = static_cast<int>(log.collisions.size());
  for (std::size_t i = 1; i < log.planned_path.size(); ++i)
    m.planned_length_m += (log.planned_path[i] - log.planned_path[i - 1]).norm();
  m.error_reference = reference;
  if (log.samples.empty()) return m;

  const double t_end = log.reached_goal ? log.arrival_time : log.samples.back().t;
  m.flight_time_s = t_end - log.samples.front().t;
  const double tracking_end = trackingEnd(log);
  double sum_sq = 0.0, estimation_sq = 0.0;
  std::size_t n = 0, saturated = 0;
  m.min_clearance_m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < log.samples.size(); ++i) {
    const LogSample& s = log.samples[i];
    if (i > 0) {
      const LogSample& prev = log.samples[i - 1];
      const double dt = s.t - prev.t;
      m.flown_length_m += (s.pos - prev.pos).norm();
      m.energy_proxy += dt * prev.rotor_thrust.cwiseMax(0.0).array().pow(1.5).sum();
    }
    m.max_speed_mps = std::max(m.max_speed_mps, s.vel.norm());
    if (log.max_thrust > 0)
      m.peak_thrust_fraction =
          std::max(m.peak_thrust_fraction, s.rotor_thrust.maxCoeff() / log.max_thrust);
    saturated += s.saturated ? 1 : 0;
    estimation_sq += (s.est_pos - s.pos).squaredNorm();
    // Clearance over the whole run (hovering at the goal can be close to something too).
    m.min_clearance_m = std::min(m.min_clearance_m, world.distanceToObstacles(s.pos) - log.radius);
    if (s.t > tracking_end) continue;  // tracking error only up to arrival or a reference's end
    const double e = error_against_trajectory ? (s.pos - s.ref_pos).norm()
                                              : distanceToPolyline(s.pos, log.planned_path);
    sum_sq += e * e;
    m.max_error_m = std::max(m.max_error_m, e);
    ++n;
  }
  m.rmse_m = n ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0;
  m.saturated_fraction = static_cast<double>(saturated) / static_cast<double>(log.samples.size());
  m.estimation_rmse_m = std::sqrt(estimation_sq / static_cast<double>(log.samples.size()));
  return m;
}

}  // namespace cosim
