// The grid planners' shared behaviour: move sets and their optimal lengths, the corner-cutting
// switch, failures (unreachable goal, blocked start, time limit) and reuse across queries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "planning/grid/astar.h"
#include "planning/grid/basic_theta_star.h"
#include "planning/grid/bellman_ford.h"
#include "planning/grid/dijkstra.h"
#include "planning/grid/lazy_theta_star.h"
#include "core/input_error.h"

using namespace cosim;

namespace {

std::vector<std::unique_ptr<GridPlanner>> allPlanners(const GridMoves& moves) {
  std::vector<std::unique_ptr<GridPlanner>> v;
  v.push_back(std::make_unique<Dijkstra>(moves));
  v.push_back(std::make_unique<BellmanFord>(moves));
  v.push_back(std::make_unique<AStar>(AStar::Options{moves, 1.0}));
  v.push_back(std::make_unique<BasicThetaStar>(moves));
  v.push_back(std::make_unique<LazyThetaStar>(moves));
  return v;
}

std::vector<std::unique_ptr<GridPlanner>> optimalPlanners(const GridMoves& moves) {
  auto v = allPlanners(moves);
  v.resize(3);
  return v;
}

GridQuery query(const OccupancyGrid& g, Cell s, Cell t) {
  GridQuery q;
  q.grid = &g;
  q.start = s;
  q.goal = t;
  return q;
}

const double kSqrt2 = std::sqrt(2.0), kSqrt3 = std::sqrt(3.0);

}  // namespace

TEST(GridSearch, OptimalLengthsOnEmptyGridsFollowTheMoveSet) {
  const OccupancyGrid g2(12, 9), g3(8, 7, 6);
  const GridQuery q2 = query(g2, {1, 1, 0}, {9, 4, 0});  // dx 8, dy 3
  const GridQuery q3 = query(g3, {0, 0, 0}, {5, 3, 2});  // dx 5, dy 3, dz 2
  for (auto& p : optimalPlanners({4, false}))
    EXPECT_NEAR(p->solveGrid(q2, StopToken::untimed()).length, 11.0, 1e-9);
  for (auto& p : optimalPlanners({8, false}))
    EXPECT_NEAR(p->solveGrid(q2, StopToken::untimed()).length, 5 + 3 * kSqrt2, 1e-9) << p->name();
  for (auto& p : optimalPlanners({6, false}))
    EXPECT_NEAR(p->solveGrid(q3, StopToken::untimed()).length, 10.0, 1e-9);
  // 18 moves (no body diagonals): 3 x-y and 2 x-z face diagonals cover the offset exactly.
  for (auto& p : optimalPlanners({18, false}))
    EXPECT_NEAR(p->solveGrid(q3, StopToken::untimed()).length, 5 * kSqrt2, 1e-9) << p->name();
  for (auto& p : optimalPlanners({26, false}))
    EXPECT_NEAR(p->solveGrid(q3, StopToken::untimed()).length, 2 * kSqrt3 + kSqrt2 + 2, 1e-9)
        << p->name();
  // connectivity 0 means all moves for the grid's dimensionality.
  for (auto& p : optimalPlanners({0, false})) {
    EXPECT_NEAR(p->solveGrid(q2, StopToken::untimed()).length, 5 + 3 * kSqrt2, 1e-9) << p->name();
    EXPECT_NEAR(p->solveGrid(q3, StopToken::untimed()).length, 2 * kSqrt3 + kSqrt2 + 2, 1e-9)
        << p->name();
  }
}

TEST(GridSearch, DiagonalBetweenTwoBlockedCellsNeedsCornerCutting) {
  // . #
  // # .   the only way from (0,0) to (1,1) is the diagonal squeezing between the two walls.
  OccupancyGrid g(2, 2);
  g.setBlocked(1, 0, 0, true);
  g.setBlocked(0, 1, 0, true);
  for (auto& p : allPlanners({8, false})) {
    const GridPlanResult r = p->solveGrid(query(g, {0, 0, 0}, {1, 1, 0}), StopToken::untimed());
    EXPECT_FALSE(r.success) << p->name();
    EXPECT_EQ(r.message, "no path") << p->name();
  }
  for (auto& p : allPlanners({8, true})) {
    const GridPlanResult r = p->solveGrid(query(g, {0, 0, 0}, {1, 1, 0}), StopToken::untimed());
    ASSERT_TRUE(r.success) << p->name();
    EXPECT_NEAR(r.length, kSqrt2, 1e-12) << p->name();
  }
}

TEST(GridSearch, BodyDiagonalIn3DNeedsAllSixSideCellsFreeWithoutCornerCutting) {
  OccupancyGrid g(2, 2, 2);
  g.setBlocked(1, 0, 1, true);  // one side cell of the move (0,0,0) -> (1,1,1)
  AStar strict(AStar::Options{{26, false}, 1.0}), cutting(AStar::Options{{26, true}, 1.0});
  const GridQuery q = query(g, {0, 0, 0}, {1, 1, 1});
  EXPECT_NEAR(cutting.solveGrid(q, StopToken::untimed()).length, kSqrt3, 1e-12);
  // Around it: a face diagonal plus a straight move, sqrt 2 + 1.
  EXPECT_NEAR(strict.solveGrid(q, StopToken::untimed()).length, kSqrt2 + 1, 1e-12);
}

TEST(GridSearch, WalledOffGoalGivesNoPathFromEveryPlanner) {
  OccupancyGrid g(20, 20);
  for (int i = 0; i < 20; ++i) g.setBlocked(i, 10, 0, true);
  for (auto& p : allPlanners({0, false})) {
    const GridPlanResult r = p->solveGrid(query(g, {2, 2, 0}, {15, 15, 0}), StopToken::untimed());
    EXPECT_FALSE(r.success) << p->name();
    EXPECT_EQ(r.message, "no path") << p->name();
    EXPECT_GT(r.counters.at("expansions"), 150) << p->name();  // searched the whole lower half
  }
}

TEST(GridSearch, BlockedOrOutsideEndpointsAreRejectedWithAReason) {
  OccupancyGrid g(5, 5);
  g.setBlocked(0, 0, 0, true);
  for (auto& p : allPlanners({0, false})) {
    EXPECT_EQ(p->solveGrid(query(g, {0, 0, 0}, {4, 4, 0}), StopToken::untimed()).message,
              "start cell (0,0,0) is blocked");
    EXPECT_EQ(p->solveGrid(query(g, {4, 4, 0}, {7, 1, 0}), StopToken::untimed()).message,
              "goal cell (7,1,0) is outside the grid");
  }
}

TEST(GridSearch, ConnectivityOfTheWrongDimensionIsAnInputError) {
  OccupancyGrid g2(5, 5), g3(5, 5, 5);
  AStar a2(AStar::Options{{6, false}, 1.0}, "scenario.yaml");
  Dijkstra d3({8, false});
  EXPECT_THROW(a2.solveGrid(query(g2, {0, 0, 0}, {4, 4, 0}), StopToken::untimed()), InputError);
  EXPECT_THROW(d3.solveGrid(query(g3, {0, 0, 0}, {4, 4, 4}), StopToken::untimed()), InputError);
  try {
    a2.solveGrid(query(g2, {0, 0, 0}, {4, 4, 0}), StopToken::untimed());
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "scenario.yaml");
    EXPECT_EQ(e.place(), "parameter connectivity");
  }
}

TEST(GridSearch, TimeLimitStopsAnExhaustiveSearch) {
  // Every planner must label a million cells to prove the walled-in goal unreachable; a 1 ms
  // limit stops them long before that.
  OccupancyGrid g(1000, 1000);
  g.setBlocked(999, 998, 0, true);
  g.setBlocked(998, 999, 0, true);
  g.setBlocked(998, 998, 0, true);
  for (auto& p : allPlanners({0, false})) {
    GridQuery q = query(g, {0, 0, 0}, {999, 999, 0});
    q.time_limit_s = 0.001;
    const GridPlanResult r = p->solveGrid(q, StopToken::untimed());
    EXPECT_FALSE(r.success) << p->name();
    EXPECT_EQ(r.message, "time limit") << p->name();
    EXPECT_LT(r.counters.at("expansions"), 0.99e6) << p->name();
  }
}

TEST(GridSearch, PlannerGivesTheSameAnswersWhenReusedAcrossGridsOfDifferentSizes) {
  OccupancyGrid big(40, 30), small(6, 5), cube(7, 7, 7);
  for (int y = 0; y < 25; ++y) big.setBlocked(20, y, 0, true);
  for (auto& p : allPlanners({0, false})) {
    const GridQuery qb = query(big, {2, 2, 0}, {35, 2, 0});
    const GridQuery qs = query(small, {0, 0, 0}, {5, 4, 0});
    const GridQuery qc = query(cube, {0, 0, 0}, {6, 6, 6});
    const double first = p->solveGrid(qb, StopToken::untimed()).length;
    EXPECT_GT(first, 33.0) << p->name();
    const double s1 = p->solveGrid(qs, StopToken::untimed()).length;
    const double c1 = p->solveGrid(qc, StopToken::untimed()).length;
    EXPECT_DOUBLE_EQ(p->solveGrid(qb, StopToken::untimed()).length, first) << p->name();
    EXPECT_DOUBLE_EQ(p->solveGrid(qs, StopToken::untimed()).length, s1) << p->name();
    EXPECT_NEAR(c1, 6 * kSqrt3, 1e-9) << p->name();
  }
}

TEST(GridSearch, PlanAStarReturnsTheCellsOfAnOptimalPath) {
  OccupancyGrid g(5, 3);
  g.setBlocked(2, 0, 0, true);
  g.setBlocked(2, 1, 0, true);
  const GridPlanResult r = planAStar(g, {0, 0, 0}, {4, 0, 0});
  ASSERT_TRUE(r.success);
  // Over the wall through (2,2); the diagonals (1,1)-(2,2) and (2,2)-(3,1) would cut the wall's
  // corner, so each side takes one diagonal and two straight moves: 4 + 2 sqrt 2.
  EXPECT_EQ(r.cells.front(), (Cell{0, 0, 0}));
  EXPECT_EQ(r.cells.back(), (Cell{4, 0, 0}));
  for (const Cell& c : r.cells) EXPECT_TRUE(g.free(c));
  for (std::size_t i = 1; i < r.cells.size(); ++i) {
    EXPECT_LE(std::abs(r.cells[i].x - r.cells[i - 1].x), 1);
    EXPECT_LE(std::abs(r.cells[i].y - r.cells[i - 1].y), 1);
  }
  EXPECT_NEAR(r.length, 4 + 2 * kSqrt2, 1e-12);
}

TEST(GridSearch, OptimalPlannersAgreeOnRandom3DBoxWorldsForEveryMoveSet) {
  int compared = 0;
  for (const GridMoves moves :
       {GridMoves{6, false}, GridMoves{18, false}, GridMoves{26, false}, GridMoves{26, true}}) {
    auto planners = optimalPlanners(moves);
    for (int seed = 0; seed < 6; ++seed) {
      std::mt19937_64 rng(seed);
      OccupancyGrid g(24, 20, 10);
      for (int k = 0; k < 40; ++k) {
        const int x = rng() % 22, y = rng() % 18, z = rng() % 8;
        const int sx = 1 + rng() % 6, sy = 1 + rng() % 6, sz = 1 + rng() % 5;
        for (int zz = z; zz < std::min(10, z + sz); ++zz)
          for (int yy = y; yy < std::min(20, y + sy); ++yy)
            for (int xx = x; xx < std::min(24, x + sx); ++xx) g.setBlocked(xx, yy, zz, true);
      }
      const GridQuery q = query(g, {0, 0, 0}, {23, 19, 9});
      g.setBlocked(q.start, false);
      g.setBlocked(q.goal, false);
      const GridPlanResult reference = planners[0]->solveGrid(q, StopToken::untimed());  // Dijkstra
      for (std::size_t i = 1; i < planners.size(); ++i) {
        const GridPlanResult r = planners[i]->solveGrid(q, StopToken::untimed());
        ASSERT_EQ(r.success, reference.success) << planners[i]->name() << " seed " << seed;
        EXPECT_NEAR(r.length, reference.length, 1e-9) << planners[i]->name() << " seed " << seed;
        // Every step is one legal move.
        for (std::size_t k = 1; k < r.cells.size(); ++k) {
          const Cell& a = r.cells[k - 1];
          const Cell& b = r.cells[k];
          bool legal = false;
          for (const GridStep& s : gridSteps(moves, true))
            legal = legal || (a.x + s.dx == b.x && a.y + s.dy == b.y && a.z + s.dz == b.z &&
                              gridStepAllowed(g, a, s, moves.corner_cutting));
          EXPECT_TRUE(legal) << planners[i]->name() << " step " << k;
        }
        compared += reference.success;
      }
    }
  }
  EXPECT_GT(compared, 30);
}

TEST(GridSearch, WeightedAStarStaysWithinItsBoundAndExpandsLess) {
  // A 60x60 grid with a long wall: weight 3 may lengthen the path by at most a factor 3 and,
  // pulled towards the goal, expands fewer cells than optimal A*.
  OccupancyGrid g(60, 60);
  for (int y = 5; y < 60; ++y) g.setBlocked(30, y, 0, true);
  const GridQuery q = query(g, {5, 50, 0}, {55, 50, 0});
  AStar optimal, weighted(AStar::Options{{0, false}, 3.0});
  const GridPlanResult a = optimal.solveGrid(q, StopToken::untimed()),
                       w = weighted.solveGrid(q, StopToken::untimed());
  ASSERT_TRUE(a.success);
  ASSERT_TRUE(w.success);
  EXPECT_GE(w.length, a.length - 1e-9);
  EXPECT_LE(w.length, 3 * a.length);
  EXPECT_LT(w.counters.at("expansions"), a.counters.at("expansions"));
}
