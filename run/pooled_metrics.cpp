#include "run/pooled_metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosim {

namespace {

// Root of the sample-weighted mean of squares, or 0 without samples.
double pooledRms(double weighted_squares, double samples) {
  return samples > 0 ? std::sqrt(weighted_squares / samples) : 0.0;
}

}  // namespace

std::size_t trackedSamples(const VehicleLog& v) {
  if (v.samples.empty()) return 0;
  const double t_end = trackingEnd(v);
  return static_cast<std::size_t>(std::count_if(
      v.samples.begin(), v.samples.end(), [t_end](const LogSample& s) { return s.t <= t_end; }));
}

FlightMetrics poolFlightMetrics(const std::vector<FlightMetrics>& each, const RunLog& log,
                                const std::vector<std::size_t>& members) {
  if (members.size() == 1) return each[members.front()];
  FlightMetrics p;
  p.error_reference = ErrorReference::None;
  if (members.empty()) return p;
  p.reached_goal = true;
  p.min_clearance_m = std::numeric_limits<double>::infinity();
  p.error_reference = each[members.front()].error_reference;
  double tracked = 0.0, tracked_sq = 0.0, samples = 0.0, estimation_sq = 0.0, saturated = 0.0;
  for (std::size_t m : members) {
    const FlightMetrics& e = each[m];
    const double n = static_cast<double>(log.vehicles[m].samples.size());
    const double n_tracked = static_cast<double>(trackedSamples(log.vehicles[m]));
    p.reached_goal = p.reached_goal && e.reached_goal;
    p.collisions += e.collisions;
    p.planned_length_m += e.planned_length_m;
    p.flown_length_m += e.flown_length_m;
    p.energy_proxy += e.energy_proxy;
    p.flight_time_s = std::max(p.flight_time_s, e.flight_time_s);
    p.max_error_m = std::max(p.max_error_m, e.max_error_m);
    p.peak_thrust_fraction = std::max(p.peak_thrust_fraction, e.peak_thrust_fraction);
    p.max_speed_mps = std::max(p.max_speed_mps, e.max_speed_mps);
    p.min_clearance_m = std::min(p.min_clearance_m, e.min_clearance_m);
    if (e.error_reference != p.error_reference) p.error_reference = ErrorReference::Mixed;
    tracked += n_tracked;
    tracked_sq += e.rmse_m * e.rmse_m * n_tracked;
    samples += n;
    estimation_sq += e.estimation_rmse_m * e.estimation_rmse_m * n;
    saturated += e.saturated_fraction * n;
  }
  p.rmse_m = pooledRms(tracked_sq, tracked);
  p.estimation_rmse_m = pooledRms(estimation_sq, samples);
  p.saturated_fraction = samples > 0 ? saturated / samples : 0.0;
  return p;
}

double longestSaturation(const VehicleLog& v) {
  double longest = 0.0, since = -1.0;
  for (const auto& x : v.samples) {
    if (!x.saturated)
      since = -1.0;
    else if (since < 0.0)
      since = x.t;
    else
      longest = std::max(longest, x.t - since);
  }
  return longest;
}

}  // namespace cosim
