// Grids from worlds with seed 003's blocking rule (cell_blocking: centre): a cell is blocked only
// when its centre lies inside an obstacle, so its point-mass plans may graze obstacle faces, as
// the thesis's did; the default blocks every cell any point of which is near an obstacle.
#include <gtest/gtest.h>

#include "experiments/reproduce/seed003_maps.h"
#include "planning/grid/basic_theta_star.h"
#include "planning/planner_registry.h"

namespace cosim {
namespace {

TEST(GridCellBlocking, CentreRuleIsSeed003sGridAndBlocksFewerCellsThanTheDefault) {
  const Seed003Map map = seed003Maps()[3];
  const OccupancyGrid thesis = seed003Grid(map);
  const OccupancyGrid centre =
      OccupancyGrid::fromWorld(map.world, 1.0, 0.0, false, 0.0, OccupancyGrid::Blocking::Centre);
  const OccupancyGrid any = OccupancyGrid::fromWorld(map.world, 1.0, 0.0);
  ASSERT_EQ(centre.cellCount(), thesis.cellCount());
  for (std::size_t i = 0; i < centre.cellCount(); ++i)
    ASSERT_EQ(centre.blocked(centre.cellAt(i)), thesis.blocked(thesis.cellAt(i))) << i;
  // The boxes lie on whole metres: the centre rule blocks exactly their cells (2 x 26 x 5 +
  // 2 x 30 x 5 + 2 x 33 x 5 + 6 x 6 x 3 + 8 x 6 x 3 = 1142), the default adds every neighbour.
  EXPECT_EQ(centre.blockedCount(), 1142u);
  EXPECT_GT(any.blockedCount(), 2 * centre.blockedCount());
}

TEST(GridCellBlocking, ThetaStarWithTheCentreRulePlansSeed003DiscretesPath) {
  const Seed003Map map = seed003Maps()[3];
  const OccupancyGrid grid = seed003Grid(map);
  GridQuery q;
  q.grid = &grid;
  q.start = grid.cellOf(map.start);
  q.goal = grid.cellOf(map.goal);
  const GridPlanResult discrete = BasicThetaStar().solveGrid(q, StopToken::untimed());
  ASSERT_TRUE(discrete.success);
  ParamSet p("test");
  p.set("resolution", "1.0");
  p.set("cell_blocking", "centre");
  PlanningProblem prob;
  prob.world = &map.world;
  prob.start = map.start;  // cell centres, so the world path adds no end segments
  prob.goal = map.goal;
  const PlanResult world = makePlanner("theta_star", p)->solve(prob, StopToken::untimed());
  ASSERT_TRUE(world.success) << world.message;
  EXPECT_NEAR(world.path.length(), discrete.length, 1e-9);
  EXPECT_NEAR(world.path.length(), 78.19, 0.005);  // seed003-discrete's map 3 path
  // The conservative rule keeps half a cell diagonal (0.87 m) off every face: a longer path.
  p = ParamSet("test");
  p.set("resolution", "1.0");
  p.set("cell_blocking", "cell");
  EXPECT_GT(makePlanner("theta_star", p)->solve(prob, StopToken::untimed()).path.length(),
            world.path.length() + 3.0);
  // The default (exact) rule for a point mass: free centres as the thesis's, but every segment
  // checked against the obstacles, so never shorter than the thesis's path.
  p = ParamSet("test");
  p.set("resolution", "1.0");
  const PlanResult exact = makePlanner("theta_star", p)->solve(prob, StopToken::untimed());
  ASSERT_TRUE(exact.success) << exact.message;
  EXPECT_GE(exact.path.length(), world.path.length() - 1e-9);
}

}  // namespace
}  // namespace cosim
