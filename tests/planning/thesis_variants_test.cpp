// The thesis variants the reproductions run: seed 004's diagonal rule (§4.2: a diagonal move
// only when all four cells it touches are free) and seed 000's randomly turning moving obstacles
// (§4.2.3), drawn in advance from a seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "planning/grid/lazy_theta_star.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/navigation/randomly_turning_obstacle.h"

namespace cosim {
namespace {

bool hasMove(const MapfGrid& g, const Cell& a, const Cell& b) {
  const auto n = g.neighbours(g.id(a));
  return std::find(n.begin(), n.end(), g.id(b)) != n.end();
}

TEST(Seed004DiagonalRule, ADiagonalMoveNeedsAllFourCellsFree) {
  OccupancyGrid open(3, 3);
  const MapfGrid all_free(open, 8);
  EXPECT_TRUE(hasMove(all_free, {0, 0, 0}, {1, 1, 0}));
  EXPECT_EQ(all_free.neighbours(all_free.id({1, 1, 0})).size(), 8u);
  // One side cell blocked: (0,0) -> (1,1) touches (1,0), so it is gone; straight moves stay.
  OccupancyGrid one_side = open;
  one_side.setBlocked(1, 0, 0, true);
  const MapfGrid g(one_side, 8);
  EXPECT_FALSE(hasMove(g, {0, 0, 0}, {1, 1, 0}));
  EXPECT_FALSE(hasMove(g, {1, 1, 0}, {0, 0, 0}));
  EXPECT_FALSE(hasMove(g, {1, 1, 0}, {2, 0, 0}));  // touches (1,0) as well
  EXPECT_TRUE(hasMove(g, {0, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(hasMove(g, {1, 1, 0}, {0, 2, 0}));        // touches (0,1), (1,2): both free
  EXPECT_EQ(g.neighbours(g.id({1, 1, 0})).size(), 5u);  // 3 straight + 2 diagonals left
  // 4-connected: never a diagonal.
  EXPECT_FALSE(hasMove(MapfGrid(open, 4), {0, 0, 0}, {1, 1, 0}));
}

// Seed 003's Lazy Theta* (Alg. 5, as Nash et al. 2010) expands a cell at once after SetVertex
// gave it a dearer parent; ours puts it back into OPEN. On this 6 x 4 map (start (0,0), goal
// (5,3); blocked (2,2), (5,2), (1,3)) the thesis's variant expands (4,3) with the parent (4,2)
// that SetVertex found, (0,0) -> (4,2) -> (4,3) -> (5,3) = sqrt(20) + 1 + 1, and never revisits
// it; ours re-queues (4,3), which then gets the cheaper (3,1) through the cell before it:
// (0,0) -> (3,1) -> (4,3) -> (5,3) = sqrt(10) + sqrt(5) + 1.
TEST(LazyThetaStarVariants, TheThesisVariantIsLongerOnAHandWorkedMap) {
  OccupancyGrid g(6, 4);
  for (const Cell& c : {Cell{2, 2, 0}, Cell{5, 2, 0}, Cell{1, 3, 0}}) g.setBlocked(c, true);
  GridQuery q;
  q.grid = &g;
  q.start = {0, 0, 0};
  q.goal = {5, 3, 0};
  LazyThetaStar ours;
  LazyThetaStar thesis(GridMoves{0, false}, "", LazyThetaStar::Variant::kExpandAtOnce);
  const GridPlanResult a = ours.solveGrid(q, StopToken::untimed()),
                       b = thesis.solveGrid(q, StopToken::untimed());
  ASSERT_TRUE(a.success);
  ASSERT_TRUE(b.success);
  EXPECT_NEAR(a.length, std::sqrt(10.0) + std::sqrt(5.0) + 1.0, 1e-9);
  EXPECT_NEAR(b.length, std::sqrt(20.0) + 2.0, 1e-9);
  EXPECT_GT(b.length, a.length);
  EXPECT_EQ(b.cells[1], (Cell{4, 2, 0}));
  EXPECT_EQ(a.cells[1], (Cell{3, 1, 0}));
}

TurningObstacleSpec roomSpec() {
  TurningObstacleSpec s;
  s.start = {3, 3, 0};
  s.direction = 1;
  s.speed = 0.7;
  s.box_min = {1, 1, 0};
  s.box_max = {10, 8, 0};
  s.travel = 300;
  return s;
}

OccupancyGrid roomWithPillar() {
  OccupancyGrid g(12, 10);
  g.setBlocked(6, 4, 0, true);
  g.setBlocked(6, 5, 0, true);
  return g;
}

TEST(RandomlyTurningObstacle, SameSeedSameRouteOtherSeedOtherRoute) {
  const OccupancyGrid g = roomWithPillar();
  const MovingObstacle a = randomlyTurningObstacle(g, roomSpec(), 7);
  const MovingObstacle b = randomlyTurningObstacle(g, roomSpec(), 7);
  const MovingObstacle c = randomlyTurningObstacle(g, roomSpec(), 8);
  EXPECT_EQ(a.waypoints(), b.waypoints());
  EXPECT_NE(a.waypoints(), c.waypoints());
  for (double t : {0.0, 3.3, 41.0, 250.0}) EXPECT_EQ(a.positionAt(t), b.positionAt(t)) << t;
  // It turns: 300 cells of travel in an 10 x 8 rectangle take many straight runs.
  EXPECT_GT(a.waypoints().size(), 10u);
  EXPECT_EQ(a.waypoints().front(), (Cell{3, 3, 0}));
  EXPECT_EQ(a.speed(), 0.7);
}

TEST(RandomlyTurningObstacle, StaysInItsRectangleOnFreeCellsMovingStraightBetweenTurns) {
  const OccupancyGrid g = roomWithPillar();
  const TurningObstacleSpec s = roomSpec();
  const MovingObstacle o = randomlyTurningObstacle(g, s, 3);
  const auto& w = o.waypoints();
  for (std::size_t i = 0; i < w.size(); ++i) {
    EXPECT_GE(w[i].x, 1);
    EXPECT_LE(w[i].x, 10);
    EXPECT_GE(w[i].y, 1);
    EXPECT_LE(w[i].y, 8);
    if (i == 0) continue;
    // A straight run: along an axis or a 45-degree diagonal, every cell on it free.
    const int dx = w[i].x - w[i - 1].x, dy = w[i].y - w[i - 1].y;
    ASSERT_TRUE(dx == 0 || dy == 0 || std::abs(dx) == std::abs(dy)) << i;
    const int steps = std::max(std::abs(dx), std::abs(dy));
    for (int k = 0; k <= steps; ++k)
      EXPECT_FALSE(g.blocked(w[i - 1].x + k * (dx > 0) - k * (dx < 0),
                             w[i - 1].y + k * (dy > 0) - k * (dy < 0), 0));
  }
}

TEST(RandomlyTurningObstacle, ABlockedStartIsAnInputError) {
  TurningObstacleSpec s = roomSpec();
  s.start = {6, 4, 0};
  EXPECT_ANY_THROW(randomlyTurningObstacle(roomWithPillar(), s, 1));
}

}  // namespace
}  // namespace cosim
