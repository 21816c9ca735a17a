#include "render/log_lookup.h"

#include <algorithm>

#include "sim/flight_metrics.h"

namespace cosim {

std::size_t sampleIndexAt(const VehicleLog& v, double t) {
  auto it = std::upper_bound(v.samples.begin(), v.samples.end(), t,
                             [](double time, const LogSample& s) { return time < s.t; });
  return it == v.samples.begin() ? 0 : static_cast<std::size_t>(it - v.samples.begin() - 1);
}

std::vector<double> trackingErrors(const VehicleLog& v, bool against_trajectory) {
  std::vector<double> e;
  e.reserve(v.samples.size());
  for (const LogSample& s : v.samples)
    e.push_back(against_trajectory || v.planned_path.size() < 2
                    ? (s.pos - s.ref_pos).norm()
                    : distanceToPolyline(s.pos, v.planned_path));
  return e;
}

double logEndTime(const RunLog& log) {
  double t = 0.0;
  for (const auto& v : log.vehicles)
    if (!v.samples.empty()) t = std::max(t, v.samples.back().t);
  return t;
}

}  // namespace cosim
