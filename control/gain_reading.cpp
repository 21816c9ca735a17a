#include "control/gain_reading.h"

namespace cosim {

Eigen::Vector3d readHorizontalAndZ(ParamSet& p, const std::string& prefix,
                                   const Eigen::Vector3d& fallback, double hi) {
  const double xy = p.getDouble(prefix + "_xy", fallback.x(), 0.0, hi);
  return {xy, xy, p.getDouble(prefix + "_z", fallback.z(), 0.0, hi)};
}

Eigen::Vector3d readRollPitchAndYaw(ParamSet& p, const std::string& prefix,
                                    const Eigen::Vector3d& fallback, double hi) {
  const double rp = p.getDouble(prefix + "_rp", fallback.x(), 0.0, hi);
  return {rp, rp, p.getDouble(prefix + "_yaw", fallback.z(), 0.0, hi)};
}

}  // namespace cosim
