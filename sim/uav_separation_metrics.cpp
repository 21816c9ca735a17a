#include "sim/uav_separation_metrics.h"

#include <algorithm>

namespace cosim {

UavSeparationMetrics uavSeparationMetrics(const RunLog& log,
                                          const std::vector<std::size_t>& quadrotors,
                                          const std::vector<SeparationEllipsoid>& separation) {
  UavSeparationMetrics m;
  const std::size_t n = quadrotors.size();
  // Contacts: each touching pair is booked by both vehicles; count it at the lower index.
  for (std::size_t a = 0; a < n; ++a)
    for (const ContactEvent& c : log.vehicles[quadrotors[a]].collisions)
      for (std::size_t b = a + 1; b < n; ++b)
        if (c.other.rfind(log.vehicles[quadrotors[b]].name + "/", 0) == 0) ++m.uav_contacts;

  std::vector<char> inside(n * n, 0);
  std::size_t samples = std::numeric_limits<std::size_t>::max();
  for (std::size_t q : quadrotors) samples = std::min(samples, log.vehicles[q].samples.size());
  if (n < 2) return m;
  for (std::size_t k = 0; k < samples; ++k) {
    for (std::size_t a = 0; a < n; ++a) {
      const Eigen::Vector3d& pa = log.vehicles[quadrotors[a]].samples[k].pos;
      for (std::size_t b = a + 1; b < n; ++b) {
        const double d = SeparationEllipsoid::between(separation[a], separation[b])
                             .distance(pa, log.vehicles[quadrotors[b]].samples[k].pos);
        m.min_uav_separation = std::min(m.min_uav_separation, d);
        char& was = inside[a * n + b];
        if (d < 1.0 && !was) ++m.downwash_violations;
        was = d < 1.0;
      }
    }
  }
  return m;
}

}  // namespace cosim
