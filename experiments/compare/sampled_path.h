#pragma once
// A position (or reference) sampled at increasing times, read between samples by linear
// interpolation: a real flight log and a run's time series are both this, at rates of their own.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace cosim {

struct SampledPath {
  std::vector<double> t;  // s, strictly increasing
  std::vector<Eigen::Vector3d> p;

  std::size_t size() const { return t.size(); }
  double start() const { return t.front(); }
  double end() const { return t.back(); }
  // The position at `time`, linear between the samples around it; the first or last sample
  // outside [start(), end()].
  Eigen::Vector3d at(double time) const;
};

}  // namespace cosim
