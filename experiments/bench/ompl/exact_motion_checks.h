#pragma once
// OMPL's view of our collision world: a StateValidityChecker and a MotionValidator that call
// CollisionWorld's exact point and segment tests. Our sampling planners check edges the same
// way (the segment against the inflated obstacles, no sampling along it), so an OMPL planner
// given these pays for, and sees, exactly the collisions ours do.
#include <ompl/base/MotionValidator.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>

#include <Eigen/Core>

#include "planning/sampling/collision_world.h"

namespace cosim::omplbench {

// A state of a 3D real vector space, or of a 2D one in the plane z = plane_z (ground robots).
Eigen::Vector3d toPoint(const ompl::base::State* state, unsigned dimension, double plane_z);

class ExactValidityChecker : public ompl::base::StateValidityChecker {
 public:
  ExactValidityChecker(const ompl::base::SpaceInformationPtr& si, const CollisionWorld& world,
                       double plane_z = 0.0);
  bool isValid(const ompl::base::State* s) const override;

 private:
  const CollisionWorld& world_;
  unsigned dimension_;
  double plane_z_;
};

class ExactMotionValidator : public ompl::base::MotionValidator {
 public:
  ExactMotionValidator(const ompl::base::SpaceInformationPtr& si, const CollisionWorld& world,
                       double plane_z = 0.0);
  bool checkMotion(const ompl::base::State* a, const ompl::base::State* b) const override;
  // Only the yes/no answer is exact: on a collision the last valid point reported is the start
  // (conservative). RRT, RRT-Connect, RRT*, Informed RRT* and PRM do not call this variant.
  bool checkMotion(const ompl::base::State* a, const ompl::base::State* b,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  const CollisionWorld& world_;
  unsigned dimension_;
  double plane_z_;
};

}  // namespace cosim::omplbench
