#include "experiments/bench/ompl/exact_motion_checks.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace cosim::omplbench {

namespace ob = ompl::base;

Eigen::Vector3d toPoint(const ob::State* state, unsigned dimension, double plane_z) {
  const auto* v = state->as<ob::RealVectorStateSpace::StateType>();
  return {v->values[0], v->values[1], dimension == 2 ? plane_z : v->values[2]};
}

bool ExactMotionValidator::checkMotion(const ob::State* a, const ob::State* b) const {
  const bool ok = view_.segmentFree(a, b);
  ok ? ++valid_ : ++invalid_;
  return ok;
}

bool ExactMotionValidator::checkMotion(const ob::State* a, const ob::State* b,
                                       std::pair<ob::State*, double>& last_valid) const {
  const bool ok = checkMotion(a, b);
  if (!ok) {
    if (last_valid.first) si_->copyState(last_valid.first, a);
    last_valid.second = 0.0;
  }
  return ok;
}

}  // namespace cosim::omplbench
