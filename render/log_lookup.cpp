#include "render/log_lookup.h"

#include <algorithm>

namespace cosim {

std::size_t sampleIndexAt(const VehicleLog& v, double t) {
  auto it = std::upper_bound(v.samples.begin(), v.samples.end(), t,
                             [](double time, const LogSample& s) { return time < s.t; });
  return it == v.samples.begin() ? 0 : static_cast<std::size_t>(it - v.samples.begin() - 1);
}

double logEndTime(const RunLog& log) {
  double t = 0.0;
  for (const auto& v : log.vehicles)
    if (!v.samples.empty()) t = std::max(t, v.samples.back().t);
  return t;
}

}  // namespace cosim
