#pragma once
// Reading a controller's gains from its `gains:` parameters where axes share a gain: a vehicle
// symmetric about z takes one gain for x and y (or for roll and pitch) and its own for z (or
// yaw). Every controller's GainTable (control/controller_gains.h) reads paired gains this way, so
// the keys follow one pattern.
#include <Eigen/Core>
#include <string>

#include "core/param_set.h"

namespace cosim {

// <prefix>_xy for x and y, <prefix>_z for z, each in [0, hi]; `fallback` gives the defaults
// (its x for both horizontal axes).
Eigen::Vector3d readHorizontalAndZ(ParamSet& p, const std::string& prefix,
                                   const Eigen::Vector3d& fallback, double hi);

// <prefix>_rp for roll and pitch, <prefix>_yaw for yaw, each in [0, hi]; `fallback` gives the
// defaults (its x for roll and pitch).
Eigen::Vector3d readRollPitchAndYaw(ParamSet& p, const std::string& prefix,
                                    const Eigen::Vector3d& fallback, double hi);

}  // namespace cosim
