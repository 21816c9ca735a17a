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

// The collision world as seen from one space: states to points, then our tests.
class WorldView {
 public:
  WorldView(const ompl::base::SpaceInformationPtr& si, const CollisionWorld& world, double plane_z)
      : world_(world), dimension_(si->getStateDimension()), plane_z_(plane_z) {}
  bool pointFree(const ompl::base::State* s) const {
    return world_.pointFree(toPoint(s, dimension_, plane_z_));
  }
  bool segmentFree(const ompl::base::State* a, const ompl::base::State* b) const {
    return world_.segmentFree(toPoint(a, dimension_, plane_z_), toPoint(b, dimension_, plane_z_));
  }

 private:
  const CollisionWorld& world_;
  unsigned dimension_;
  double plane_z_;
};

class ExactValidityChecker : public ompl::base::StateValidityChecker {
 public:
  ExactValidityChecker(const ompl::base::SpaceInformationPtr& si, const CollisionWorld& world,
                       double plane_z = 0.0)
      : ompl::base::StateValidityChecker(si), view_(si, world, plane_z) {}
  bool isValid(const ompl::base::State* s) const override { return view_.pointFree(s); }

 private:
  WorldView view_;
};

class ExactMotionValidator : public ompl::base::MotionValidator {
 public:
  ExactMotionValidator(const ompl::base::SpaceInformationPtr& si, const CollisionWorld& world,
                       double plane_z = 0.0)
      : ompl::base::MotionValidator(si), view_(si, world, plane_z) {}
  bool checkMotion(const ompl::base::State* a, const ompl::base::State* b) const override;
  // Only the yes/no answer is exact: on a collision the last valid point reported is the start
  // (conservative). RRT, RRT-Connect, RRT*, Informed RRT* and PRM do not call this variant.
  bool checkMotion(const ompl::base::State* a, const ompl::base::State* b,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  WorldView view_;
};

}  // namespace cosim::omplbench
