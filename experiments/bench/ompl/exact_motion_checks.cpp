#include "experiments/bench/ompl/exact_motion_checks.h"

#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace cosim::omplbench {

namespace ob = ompl::base;

Eigen::Vector3d toPoint(const ob::State* state, unsigned dimension, double plane_z) {
  const auto* v = state->as<ob::RealVectorStateSpace::StateType>();
  return {v->values[0], v->values[1], dimension == 2 ? plane_z : v->values[2]};
}

ExactValidityChecker::ExactValidityChecker(const ob::SpaceInformationPtr& si,
                                           const CollisionWorld& world, double plane_z)
    : ob::StateValidityChecker(si),
      world_(world),
      dimension_(si->getStateDimension()),
      plane_z_(plane_z) {}

bool ExactValidityChecker::isValid(const ob::State* s) const {
  return world_.pointFree(toPoint(s, dimension_, plane_z_));
}

ExactMotionValidator::ExactMotionValidator(const ob::SpaceInformationPtr& si,
                                           const CollisionWorld& world, double plane_z)
    : ob::MotionValidator(si),
      world_(world),
      dimension_(si->getStateDimension()),
      plane_z_(plane_z) {}

bool ExactMotionValidator::checkMotion(const ob::State* a, const ob::State* b) const {
  const bool ok =
      world_.segmentFree(toPoint(a, dimension_, plane_z_), toPoint(b, dimension_, plane_z_));
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
