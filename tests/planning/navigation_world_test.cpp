// The navigation world of seed 000's RNA experiments: moving obstacles and collision checks.
#include "planning/navigation/navigation_world.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "planning/navigation/navigator.h"

using namespace cosim;

TEST(NavigationMovingObstacle, BackAndForthRetracesItsSegment) {
  const MovingObstacle o({{0, 0, 0}, {4, 0, 0}}, 1.0);
  EXPECT_TRUE(o.positionAt(2.0).isApprox(Eigen::Vector2d(2, 0)));
  EXPECT_TRUE(o.positionAt(6.0).isApprox(Eigen::Vector2d(2, 0)));  // on its way back
  EXPECT_GT(o.velocityAt(1.0).x(), 0.9);
  EXPECT_LT(o.velocityAt(5.0).x(), -0.9);
  EXPECT_TRUE(o.positionAt(8.0).isApprox(Eigen::Vector2d(0, 0)));
}

TEST(NavigationMovingObstacle, LoopReturnsToItsFirstWaypointAcrossTheClosingSegment) {
  const MovingObstacle o({{0, 0, 0}, {3, 0, 0}, {3, 4, 0}}, 2.0, MovingObstacle::Mode::Loop);
  // Perimeter 3 + 4 + 5 = 12 cells at 2 cells per unit: back at the start at t = 6.
  EXPECT_TRUE(o.positionAt(6.0).isApprox(Eigen::Vector2d(0, 0)));
  EXPECT_TRUE(o.positionAt(2.5).isApprox(Eigen::Vector2d(3, 2)));
  // Halfway along the hypotenuse (3,4) -> (0,0).
  EXPECT_TRUE(o.positionAt(4.75).isApprox(Eigen::Vector2d(1.5, 2)));
}

TEST(NavigationMovingObstacle, BetweenCellsItOccupiesTwoOrFour) {
  const MovingObstacle straight({{0, 0, 0}, {4, 0, 0}}, 1.0);
  EXPECT_EQ(straight.cellsAt(1.0).size(), 1u);
  EXPECT_EQ(straight.cellsAt(1.5).size(), 2u);
  const MovingObstacle diagonal({{0, 0, 0}, {4, 4, 0}}, 1.0);
  EXPECT_EQ(diagonal.cellsAt(0.7).size(), 4u);
}

TEST(NavigationWorld, ObstacleCentreInMetresFollowsTheGridFrame) {
  OccupancyGrid g(10, 10, 1, 0.5, Eigen::Vector3d(1, 2, 0));
  const NavigationWorld w(g, {MovingObstacle({{2, 3, 0}, {6, 3, 0}}, 1.0)});
  // Cell (4, 3) at t = 2: centre 1 + 0.5 * 4.5 = 3.25, 2 + 0.5 * 3.5 = 3.75.
  EXPECT_TRUE(w.obstacleCentre(0, 2.0).isApprox(Eigen::Vector3d(3.25, 3.75, 0.25)));
}

TEST(NavigationWorld, WaypointInAWallIsAnInputError) {
  OccupancyGrid g(10, 10);
  g.setBlocked(5, 5, 0, true);
  EXPECT_THROW(NavigationWorld(g, {MovingObstacle({{1, 5, 0}, {5, 5, 0}}, 1.0)}), InputError);
}

TEST(NavigationWorld, HeadOnSwapIsACollisionPassingSideBySideIsNot) {
  const OccupancyGrid g(10, 10);
  // Obstacle moves (5,5) -> (4,5) during [0, 1] at speed 1.
  const NavigationWorld w(g, {MovingObstacle({{5, 5, 0}, {0, 5, 0}}, 1.0)});
  EXPECT_TRUE(w.robotHitsObstacle({4, 5, 0}, {5, 5, 0}, 0.0, 1.0));
  EXPECT_FALSE(w.robotHitsObstacle({4, 6, 0}, {5, 6, 0}, 0.0, 1.0));  // the lane beside
  EXPECT_TRUE(w.robotHitsObstacle({2, 5, 0}, {2, 5, 0}, 2.5, 1.0));   // waiting on its track
}

namespace {
// A robot that stands still: on an obstacle's track it must be hit.
class StandStill : public Navigator {
 public:
  std::string name() const override { return "stand_still"; }
  void reset(const NavigationWorld&, const Cell&, const Cell&, std::uint64_t) override {}
  NavigationDecision decide(const Cell& at, double) override {
    NavigationDecision d;
    d.next = at;
    return d;
  }
};
}  // namespace

TEST(NavigationRun, CountsCollisionsAndStopsAtTheDecisionLimit) {
  const OccupancyGrid g(10, 10);
  const NavigationWorld w(g, {MovingObstacle({{0, 5, 0}, {9, 5, 0}}, 1.0)});
  StandStill robot;
  NavigationLimits limits;
  limits.max_decisions = 18;  // one trip of 9 cells there and back
  const NavigationRun run = runNavigation(robot, w, {4, 5, 0}, {9, 9, 0}, limits, 1);
  EXPECT_FALSE(run.reached);
  EXPECT_EQ(run.waits, 18);
  // Passed at t = 4 going out and t = 14 coming back; each pass overlaps the waits around it.
  EXPECT_GE(run.collisions, 2);
  EXPECT_LE(run.collisions, 4);
  EXPECT_EQ(run.message, "decision limit reached");
}

TEST(NavigationWorld, ASegmentThroughAWallIsAnInputErrorEvenBetweenFreeWaypoints) {
  OccupancyGrid g(10, 10);
  g.setBlocked(4, 5, 0, true);
  EXPECT_THROW(NavigationWorld(g, {MovingObstacle({{1, 5, 0}, {8, 5, 0}}, 1.0)}), InputError);
  // Back and forth never travels from the last waypoint to the first: no closing segment.
  EXPECT_NO_THROW(NavigationWorld(g, {MovingObstacle({{1, 6, 0}, {8, 6, 0}, {8, 4, 0}}, 1.0)}));
  // A loop does: (8, 4) -> (1, 6) passes (4, 5).
  EXPECT_THROW(NavigationWorld(g, {MovingObstacle({{1, 6, 0}, {8, 6, 0}, {8, 4, 0}}, 1.0,
                                                  MovingObstacle::Mode::Loop)}),
               InputError);
}
