// Basic Theta* and Lazy Theta*: their segments never touch a blocked cell (checked by an exact
// segment-box test written independently of the planners' supercover walk) and their paths are
// never longer than A*'s on the same query, in 2D and 3D.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "planning/grid/astar.h"
#include "planning/grid/basic_theta_star.h"
#include "planning/grid/grid_line_of_sight.h"
#include "planning/grid/lazy_theta_star.h"
#include "planning/grid/movingai.h"

using namespace cosim;

namespace {

// Does the segment between the centres of a and b meet the closed unit cube of cell q? Slab test
// on the parametric segment, with the cube grown by 1e-9 so that touching an edge or a corner
// counts (the supercover convention).
bool segmentTouchesCell(const Cell& a, const Cell& b, const Cell& q) {
  const double p0[3] = {a.x + 0.5, a.y + 0.5, a.z + 0.5};
  const double d[3] = {double(b.x - a.x), double(b.y - a.y), double(b.z - a.z)};
  const double lo[3] = {q.x - 1e-9, q.y - 1e-9, q.z - 1e-9};
  const double hi[3] = {q.x + 1 + 1e-9, q.y + 1 + 1e-9, q.z + 1 + 1e-9};
  double t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (p0[i] < lo[i] || p0[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - p0[i]) / d[i], tb = (hi[i] - p0[i]) / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// Independent reference for line of sight: every cell in the bounding box is tested.
bool segmentClear(const OccupancyGrid& g, const Cell& a, const Cell& b) {
  for (int z = std::min(a.z, b.z) - 1; z <= std::max(a.z, b.z) + 1; ++z)
    for (int y = std::min(a.y, b.y) - 1; y <= std::max(a.y, b.y) + 1; ++y)
      for (int x = std::min(a.x, b.x) - 1; x <= std::max(a.x, b.x) + 1; ++x)
        if (g.blocked(x, y, z) && g.inside(x, y, z) && segmentTouchesCell(a, b, {x, y, z}))
          return false;
  return true;
}

OccupancyGrid randomGrid(int nx, int ny, int nz, double density, std::uint64_t seed) {
  OccupancyGrid g(nx, ny, nz);
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution blocked(density);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) g.setBlocked(x, y, z, blocked(rng));
  return g;
}

Cell randomFreeCell(const OccupancyGrid& g, std::mt19937_64& rng) {
  for (;;) {
    const Cell c{int(rng() % g.nx()), int(rng() % g.ny()), int(rng() % g.nz())};
    if (g.free(c)) return c;
  }
}

// Runs A*, Basic Theta* and Lazy Theta* on `queries` random queries; checks every segment of the
// any-angle paths and their lengths against A*. Returns how many queries were solved.
int checkAnyAngleAgainstAStar(const OccupancyGrid& g, int queries, std::uint64_t seed) {
  AStar astar;
  BasicThetaStar theta;
  LazyThetaStar lazy;
  std::mt19937_64 rng(seed);
  int solved = 0;
  for (int k = 0; k < queries; ++k) {
    GridQuery q;
    q.grid = &g;
    q.start = randomFreeCell(g, rng);
    q.goal = randomFreeCell(g, rng);
    const GridPlanResult a = astar.solveGrid(q, StopToken::untimed());
    for (GridPlanner* p : {static_cast<GridPlanner*>(&theta), static_cast<GridPlanner*>(&lazy)}) {
      const GridPlanResult r = p->solveGrid(q, StopToken::untimed());
      EXPECT_EQ(r.success, a.success) << p->name() << " query " << k;
      if (!r.success || !a.success) continue;
      EXPECT_LE(r.length, a.length + 1e-9) << p->name() << " query " << k;
      EXPECT_EQ(r.cells.front(), q.start);
      EXPECT_EQ(r.cells.back(), q.goal);
      for (std::size_t i = 1; i < r.cells.size(); ++i)
        EXPECT_TRUE(segmentClear(g, r.cells[i - 1], r.cells[i]))
            << p->name() << " query " << k << " segment " << i;
    }
    solved += a.success;
  }
  return solved;
}

}  // namespace

TEST(GridLineOfSight, AgreesWithExactSegmentTestOnRandom2DAnd3DSegments) {
  int blocked_seen = 0, clear_seen = 0;
  for (int nz : {1, 6}) {
    const OccupancyGrid g = randomGrid(14, 12, nz, 0.12, 7 + nz);
    std::mt19937_64 rng(99);
    for (int k = 0; k < 4000; ++k) {
      const Cell a{int(rng() % 14), int(rng() % 12), int(rng() % nz)};
      const Cell b{int(rng() % 14), int(rng() % 12), int(rng() % nz)};
      const bool expected = g.free(a) && segmentClear(g, a, b);
      ASSERT_EQ(gridLineOfSight(g, a, b), expected)
          << "(" << a.x << "," << a.y << "," << a.z << ") -> (" << b.x << "," << b.y << "," << b.z
          << ")";
      (expected ? clear_seen : blocked_seen)++;
    }
  }
  // Both outcomes must be exercised, or the comparison proves nothing.
  EXPECT_GT(blocked_seen, 1000);
  EXPECT_GT(clear_seen, 500);
}

TEST(GridLineOfSight, SegmentThroughACornerIsBlockedByEitherDiagonalCell) {
  OccupancyGrid g(3, 3);
  g.setBlocked(1, 0, 0, true);
  // (0,0)->(1,1) and (0,0)->(2,2) pass exactly through the corner shared with (1,0) and (0,1).
  EXPECT_FALSE(gridLineOfSight(g, {0, 0, 0}, {1, 1, 0}));
  EXPECT_FALSE(gridLineOfSight(g, {0, 0, 0}, {2, 2, 0}));
  EXPECT_TRUE(gridLineOfSight(g, {0, 1, 0}, {2, 2, 0}));  // passes above the blocked cell
  OccupancyGrid h(3, 3, 3);
  h.setBlocked(1, 0, 1, true);  // one of the 8 cells around the corner (1,1,1) of a body step
  EXPECT_FALSE(gridLineOfSight(h, {0, 0, 0}, {1, 1, 1}));
  EXPECT_TRUE(gridLineOfSight(h, {0, 0, 0}, {0, 1, 1}));
}

TEST(GridAnyAngle, ThetaPathsAreClearAndNoLongerThanAStarIn2D) {
  const OccupancyGrid g = randomGrid(60, 50, 1, 0.25, 3);
  EXPECT_GT(checkAnyAngleAgainstAStar(g, 60, 11), 30);
}

TEST(GridAnyAngle, ThetaPathsAreClearAndNoLongerThanAStarIn3D) {
  const OccupancyGrid g = randomGrid(24, 22, 12, 0.3, 5);
  EXPECT_GT(checkAnyAngleAgainstAStar(g, 30, 13), 15);
}

TEST(GridAnyAngle, ThetaPathsAreClearAndNoLongerThanAStarOnAMovingAIMaze) {
  const OccupancyGrid g = readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/maze-32-32-2.map");
  EXPECT_GT(checkAnyAngleAgainstAStar(g, 80, 17), 60);
}

TEST(GridAnyAngle, ThetaStarIsShorterThanAStarInTheOpen) {
  // In an empty 2D grid from (0,0) to (10,3): A* needs 7 straight + 3 diagonal moves,
  // 7 + 3 sqrt 2 = 11.2426; the any-angle planners go straight, sqrt(109) = 10.4403.
  OccupancyGrid g(12, 5);
  GridQuery q;
  q.grid = &g;
  q.goal = {10, 3, 0};
  EXPECT_NEAR(AStar().solveGrid(q, StopToken::untimed()).length, 7 + 3 * std::sqrt(2.0), 1e-9);
  BasicThetaStar theta;
  LazyThetaStar lazy;
  const GridPlanResult t = theta.solveGrid(q, StopToken::untimed()),
                       l = lazy.solveGrid(q, StopToken::untimed());
  EXPECT_NEAR(t.length, std::sqrt(109.0), 1e-9);
  EXPECT_NEAR(l.length, std::sqrt(109.0), 1e-9);
  EXPECT_EQ(t.cells.size(), 2u);
  // Lazy Theta* checks line of sight once per expansion, Basic Theta* once per neighbour.
  EXPECT_LT(l.counters.at("los_checks"), t.counters.at("los_checks"));
}

TEST(GridAnyAngle, LazyThetaStarMakesFewerLineOfSightChecksThanBasicOnACluttered3DGrid) {
  const OccupancyGrid g = randomGrid(30, 30, 10, 0.2, 21);
  std::mt19937_64 rng(5);
  BasicThetaStar theta;
  LazyThetaStar lazy;
  double basic_checks = 0, lazy_checks = 0;
  for (int k = 0; k < 10; ++k) {
    GridQuery q;
    q.grid = &g;
    q.start = randomFreeCell(g, rng);
    q.goal = randomFreeCell(g, rng);
    basic_checks += theta.solveGrid(q, StopToken::untimed()).counters["los_checks"];
    lazy_checks += lazy.solveGrid(q, StopToken::untimed()).counters["los_checks"];
  }
  // Seed 003 reports about 10x fewer on its 3D maps of large obstacles (Tabs. 2-4); random
  // single-voxel clutter fails more lazy checks, and 4-5x is measured here.
  EXPECT_GT(basic_checks, 3 * lazy_checks);
}
