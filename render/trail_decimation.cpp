#include "render/trail_decimation.h"

#include <algorithm>
#include <cmath>

#include "planning/world/segment_distance.h"

namespace cosim {

std::vector<std::size_t> decimateTrail(const std::vector<LogSample>& samples,
                                       const std::vector<double>& values,
                                       const TrailDecimation& o) {
  std::vector<std::size_t> kept;
  if (samples.empty()) return kept;
  kept.push_back(0);
  std::size_t from = 0;
  while (from + 1 < samples.size()) {
    // Extend the chord from `from` while every sample it skips stays within the tolerance.
    std::size_t good = from + 1;
    for (std::size_t i = from + 2; i < samples.size(); ++i) {
      const Eigen::Vector3d& a = samples[from].pos;
      const Eigen::Vector3d& b = samples[i].pos;
      if ((b - a).norm() > o.max_segment || std::abs(values[i] - values[from]) > o.max_error_step)
        break;
      bool within = true;
      // Checking every skipped sample is quadratic in the segment's samples; a stride keeps it
      // cheap (the samples are 2 ms apart, far denser than the tolerance matters).
      const std::size_t stride = std::max<std::size_t>(1, (i - from) / 24);
      for (std::size_t j = from + 1; j < i && within; j += stride)
        within = distanceToSegment(samples[j].pos, a, b) <= o.tolerance;
      if (!within) break;
      good = i;
    }
    kept.push_back(good);
    from = good;
  }
  return kept;
}

std::vector<Eigen::Vector3d> polylineCorners(const std::vector<Eigen::Vector3d>& points) {
  constexpr double kSame = 1e-9;  // m
  std::vector<Eigen::Vector3d> corners;
  for (const Eigen::Vector3d& p : points) {
    if (!corners.empty() && (p - corners.back()).norm() < kSame) continue;
    // The last corner lies on the line from the one before it to p: it is no corner.
    if (corners.size() >= 2 &&
        distanceToSegment(corners.back(), corners[corners.size() - 2], p) < kSame &&
        (corners.back() - corners[corners.size() - 2]).dot(p - corners.back()) > 0)
      corners.pop_back();
    corners.push_back(p);
  }
  return corners;
}

}  // namespace cosim
