#pragma once
// A position (or reference) sampled at increasing times, read between samples by linear
// interpolation: a real flight log and a run's time series are both this, at rates of their own.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace cosim {

// A coordinate further than this from the origin (m) is not a flight: 1000 km, beyond any room
// or field a comparison is made in, and far below where the comparison's squares overflow.
constexpr double kMaxFlightCoordinateM = 1e6;

struct SampledPath {
  std::vector<double> t;  // s, strictly increasing
  std::vector<Eigen::Vector3d> p;

  std::size_t size() const { return t.size(); }
  double start() const { return t.front(); }
  double end() const { return t.back(); }
  // The position at `time`, linear between the samples around it; the first or last sample
  // outside [start(), end()].
  Eigen::Vector3d at(double time) const;
  // The same path on a clock that reads `origin` less: times t - origin. A log stamped in epoch
  // seconds (1e9 s and more, where a double resolves microseconds no longer) is searched on
  // times counted from its first sample this way.
  SampledPath shifted(double origin) const;
};

}  // namespace cosim
