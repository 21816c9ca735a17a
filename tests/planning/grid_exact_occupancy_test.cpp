// Grid planners on worlds with exact occupancy at cell centres: a cell is free iff the
// vehicle can stand at its centre, and every move and line of sight is checked against the
// inflated obstacles, so a grid planner is complete at its resolution and its paths are clear.
// Paths are checked independently (path_clearance_check.h); failures say why.
#include <gtest/gtest.h>

#include "planning/planner_registry.h"
#include "planning/world/generators/forest_generator.h"
#include "tests/planning/path_clearance_check.h"

namespace cosim {
namespace {

PlanResult plan(const std::string& name, const PlanningProblem& prob,
                const std::map<std::string, std::string>& params = {}) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  return makePlanner(name, p)->solve(prob, StopToken::untimed());
}

// The forest of experiments/scenarios/forest.yaml (generator seed 3, density 0.08), with trunks
// as tall as the world so that the path must weave between them rather than fly over.
GeneratedWorld tallForest() {
  ForestOptions o;
  o.world.size = {50, 50, 10};
  o.world.density = 0.08;
  o.world.seed = 3;
  o.min_height_fraction = 1.0;
  return generateForest(o);
}

// Acceptance: theta_star at its default resolution (0.5 m) crosses the forest with a path an
// independent check finds clear, for quad_1500g's radius (0.385 m) with margin 0 and with the
// bundled scenarios' margin 0.3 (inflation 0.685 m). With the old rule (cell_blocking: cell: any
// point of a cell near a trunk blocks it) the second finds no path.
TEST(GridExactOccupancy, ThetaStarAtDefaultResolutionCrossesTheForest) {
  const GeneratedWorld f = tallForest();
  for (const double inflation : {0.385, 0.685}) {
    PlanningProblem prob;
    prob.world = &f.world;
    prob.start = f.start;
    prob.goal = f.goal;
    prob.inflation = inflation;
    const PlanResult r = plan("theta_star", prob);
    ASSERT_TRUE(r.success) << "inflation " << inflation << ": " << r.message;
    EXPECT_EQ(r.path.waypoints.front(), f.start);
    EXPECT_EQ(r.path.waypoints.back(), f.goal);
    EXPECT_GE(smallestPathClearance(f.world, r.path), inflation - 1e-9) << inflation;
    EXPECT_LT(r.path.length(), 1.15 * (f.goal - f.start).norm());
    EXPECT_LT(r.time_ms, 5000.0);
  }
  PlanningProblem wide;
  wide.world = &f.world;
  wide.start = f.start;
  wide.goal = f.goal;
  wide.inflation = 0.685;
  const PlanResult old = plan("theta_star", wide, {{"cell_blocking", "cell"}});
  EXPECT_FALSE(old.success);
  EXPECT_NE(old.message.find("try a finer resolution"), std::string::npos) << old.message;
}

// A ground-robot room 10 x 6 m split by a wall at x = 5 with one opening at its far end.
World splitRoom(double gap_lo, double gap_hi, double wall_x = 5.0, double thickness = 0.1) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {10, 6, 1};
  auto box = [&](double y0, double y1) {
    if (y1 <= y0) return;
    Obstacle o;
    o.pos = {wall_x, (y0 + y1) / 2, 0.5};
    o.size = {thickness, y1 - y0, 1};
    w.obstacles.push_back(o);
  };
  box(0, gap_lo);
  box(gap_hi, 6);
  return w;
}

PlanningProblem acrossRoom(const World& w, double inflation) {
  PlanningProblem prob;
  prob.world = &w;
  prob.start = {1.25, 1.25, 0.5};
  prob.goal = {8.75, 1.25, 0.5};
  prob.inflation = inflation;
  prob.planar = true;
  return prob;
}

// A thin wall between two rows of free cell centres: exact occupancy keeps both rows free, and
// only the edge checks stop the search from stepping through it. Seed 003's centre rule does
// not check edges and goes straight through (the thesis's grazing plans).
TEST(GridExactOccupancy, EdgesThroughAThinWallBetweenFreeCentresAreRejected) {
  const World w = splitRoom(5.0, 6.0, 5.0, 0.1);  // wall faces at 4.95 and 5.05, centres 4.75, 5.25
  const PlanningProblem prob = acrossRoom(w, 0.1);
  for (const char* name : {"astar", "theta_star", "lazy_theta_star", "dijkstra", "bellman_ford"}) {
    const PlanResult r = plan(name, prob);
    ASSERT_TRUE(r.success) << name << ": " << r.message;
    EXPECT_GE(smallestPathClearance(w, r.path), 0.1 - 1e-9) << name;
    EXPECT_GT(r.path.length(), 10.5) << name;  // round by the opening: 2 x about 5.4 m
    EXPECT_GT(r.counters.at("segment_checks"), 0) << name;
  }
  const PlanResult thesis = plan("theta_star", prob, {{"cell_blocking", "centre"}});
  ASSERT_TRUE(thesis.success);
  EXPECT_LT(thesis.path.length(), 8.0);  // 7.5 m straight through the wall
}

// A gap of 0.9 m with inflation 0.2: free to a vehicle whose centre stays within its middle
// 0.5 m. At 0.5 m resolution one cell centre (y = 5.25) lies there; the conservative "cell"
// rule blocks every cell within half a diagonal more and finds nothing, and says so.
TEST(GridExactOccupancy, GapNarrowerThanTheOldBlockingIsFoundAtTheSameResolution) {
  const World w = splitRoom(4.8, 5.7);
  const PlanningProblem prob = acrossRoom(w, 0.2);
  const PlanResult exact = plan("astar", prob);
  ASSERT_TRUE(exact.success) << exact.message;
  EXPECT_NEAR(smallestPathClearance(w, exact.path), 0.45, 0.01);  // through the middle of the gap
  const PlanResult cell = plan("astar", prob, {{"cell_blocking", "cell"}});
  ASSERT_FALSE(cell.success);
  // The widest passage measured at cell centres: sqrt(0.2^2 + 0.45^2) = 0.492 m at the gap.
  EXPECT_NE(cell.message.find("0.492 m from obstacles exists"), std::string::npos) << cell.message;
  EXPECT_NE(cell.message.find("finer resolution"), std::string::npos) << cell.message;
}

// No path: the message names the inflation, the resolution and the widest passage found.
TEST(GridExactOccupancy, NoPathSaysWhy) {
  const World w = splitRoom(4.8, 5.7);
  const PlanResult narrow = plan("theta_star", acrossRoom(w, 0.5));
  ASSERT_FALSE(narrow.success);
  EXPECT_NE(narrow.message.find("inflated by 0.5 m"), std::string::npos) << narrow.message;
  EXPECT_NE(narrow.message.find("resolution 0.5 m"), std::string::npos) << narrow.message;
  EXPECT_NE(narrow.message.find("keeps only 0.492 m from obstacles"), std::string::npos)
      << narrow.message;

  const World closed = splitRoom(6.0, 6.0);
  const PlanResult walled = plan("astar", acrossRoom(closed, 0.1));
  ASSERT_FALSE(walled.success);
  EXPECT_NE(walled.message.find("no chain of cells outside the obstacles"), std::string::npos)
      << walled.message;

  PlanningProblem blocked = acrossRoom(w, 0.2);
  blocked.start = {4.9, 2.0, 0.5};  // 0.05 m from the wall's face, inside the inflation
  const PlanResult start = plan("astar", blocked);
  ASSERT_FALSE(start.success);
  EXPECT_EQ(start.message.rfind("start cell is blocked at resolution 0.5 m, obstacles inflated by "
                                "0.2 m",
                                0),
            0u)
      << start.message;
  EXPECT_NE(start.message.find("centre is 0.2 m from"), std::string::npos) << start.message;
  EXPECT_NE(start.message.find("(4.9, 2, 0.5) itself is 0.05 m away"), std::string::npos)
      << start.message;
}

}  // namespace
}  // namespace cosim
