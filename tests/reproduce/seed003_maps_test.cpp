// Seed 003's maps (experiments/reproduce/seed003_maps.h) as worlds and as the thesis's grids,
// planned through the registry (GridWorldPlanner) and by Basic Theta* directly.
#include "experiments/reproduce/seed003_maps.h"

#include <gtest/gtest.h>

#include "planning/grid/basic_theta_star.h"
#include "planning/planner_registry.h"

using namespace cosim;

TEST(Seed003Maps, ThetaStarFliesOverTheWallsOfMap1) {
  // Through the registry on the world (0.5 m voxels, 0.3 m inflation): the path exists, runs
  // from the exact start to the exact goal, and keeps the inflated vehicle off the obstacles.
  const Seed003Map map = seed003Maps()[1];
  ParamSet params("test");
  params.set("resolution", "0.5");
  auto planner = makePlanner("theta_star", params);
  PlanningProblem problem;
  problem.world = &map.world;
  problem.start = map.start;
  problem.goal = map.goal;
  problem.inflation = 0.3;
  const PlanResult r = planner->solve(problem, StopToken::untimed());
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_EQ(r.path.waypoints.front(), map.start);
  EXPECT_EQ(r.path.waypoints.back(), map.goal);
  EXPECT_GT(r.path.length(), (map.goal - map.start).norm());
  for (std::size_t i = 1; i < r.path.waypoints.size(); ++i)
    for (int k = 0; k <= 50; ++k) {
      const Eigen::Vector3d p =
          r.path.waypoints[i - 1] + (r.path.waypoints[i] - r.path.waypoints[i - 1]) * (k / 50.0);
      EXPECT_GT(map.world.distanceToObstacles(p), 0.3) << "segment " << i << " sample " << k;
    }
  EXPECT_GT(r.counters.at("los_checks"), 0);
}

TEST(Seed003Maps, GridsHaveTheThesisSizesAndFreeEndpoints) {
  const auto maps = seed003Maps();
  ASSERT_EQ(maps.size(), 4u);
  const int sizes[4][3] = {{25, 25, 1}, {20, 20, 15}, {20, 20, 10}, {50, 50, 5}};
  // Straight-line start-goal distances of the thesis (summary section 3.2).
  const double straight[4] = {29.00, 23.15, 11.58, 62.97};
  for (int k = 0; k < 4; ++k) {
    const OccupancyGrid g = seed003Grid(maps[k]);
    EXPECT_EQ(g.nx(), sizes[k][0]);
    EXPECT_EQ(g.ny(), sizes[k][1]);
    EXPECT_EQ(g.nz(), sizes[k][2]);
    Cell s = g.cellOf(maps[k].start), t = g.cellOf(maps[k].goal);
    if (maps[k].planar) s.z = t.z = 0;
    EXPECT_TRUE(g.free(s)) << maps[k].name;
    EXPECT_TRUE(g.free(t)) << maps[k].name;
    EXPECT_NEAR((maps[k].goal - maps[k].start).norm(), straight[k], 0.005) << maps[k].name;
    // Basic Theta* must detour: every map's obstacles block the straight line.
    BasicThetaStar theta;
    GridQuery q;
    q.grid = &g;
    q.start = s;
    q.goal = t;
    const GridPlanResult r = theta.solveGrid(q, StopToken::untimed());
    ASSERT_TRUE(r.success) << maps[k].name;
    EXPECT_GT(r.length, straight[k] * 1.1) << maps[k].name;
  }
}
