#include "experiments/compare/sampled_path.h"

#include <algorithm>

namespace cosim {

Eigen::Vector3d SampledPath::at(double time) const {
  if (time <= t.front()) return p.front();
  if (time >= t.back()) return p.back();
  const std::size_t hi =
      static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin());
  const std::size_t lo = hi - 1;
  const double w = (time - t[lo]) / (t[hi] - t[lo]);
  return (1.0 - w) * p[lo] + w * p[hi];
}

SampledPath SampledPath::shifted(double origin) const {
  SampledPath out;
  out.t.reserve(t.size());
  for (const double time : t) out.t.push_back(time - origin);
  out.p = p;
  return out;
}

}  // namespace cosim
