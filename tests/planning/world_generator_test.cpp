// World generators for sweeps: deterministic in their seed, density means what the headers say,
// start and goal are clear, and the maze and the city are always connected.
#include <gtest/gtest.h>

#include <cmath>
#include <queue>

#include "planning/grid/occupancy_grid.h"
#include "core/input_error.h"
#include "planning/world/generators/city_generator.h"
#include "planning/world/generators/forest_generator.h"
#include "planning/world/generators/maze_world_generator.h"

namespace cosim {
namespace {

bool sameObstacles(const World& a, const World& b) {
  if (a.obstacles.size() != b.obstacles.size()) return false;
  for (std::size_t i = 0; i < a.obstacles.size(); ++i)
    if (a.obstacles[i].pos != b.obstacles[i].pos || a.obstacles[i].size != b.obstacles[i].size ||
        a.obstacles[i].radius != b.obstacles[i].radius)
      return false;
  return true;
}

// Breadth-first search on a one-layer voxelisation at the flight height, inflated like cosim run
// inflates for a quad_1500g (radius 0.35 m + margin 0.3 m).
bool connectedAtFlightHeight(const GeneratedWorld& g) {
  const OccupancyGrid grid = OccupancyGrid::fromWorld(g.world, 0.5, 0.65, true, g.start.z());
  const Cell s = grid.cellOf(g.start), t = grid.cellOf(g.goal);
  if (grid.blocked(s) || grid.blocked(t)) return false;
  std::vector<char> seen(static_cast<std::size_t>(grid.nx()) * grid.ny(), 0);
  std::queue<Cell> open;
  open.push(s);
  seen[static_cast<std::size_t>(s.y) * grid.nx() + s.x] = 1;
  while (!open.empty()) {
    const Cell c = open.front();
    open.pop();
    if (c.x == t.x && c.y == t.y) return true;
    const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const Cell n{c.x + dx[k], c.y + dy[k], 0};
      if (grid.blocked(n)) continue;
      char& flag = seen[static_cast<std::size_t>(n.y) * grid.nx() + n.x];
      if (!flag) flag = 1, open.push(n);
    }
  }
  return false;
}

TEST(WorldGenerator, ForestIsDeterministicInItsSeed) {
  ForestOptions o;
  o.world.seed = 7;
  const GeneratedWorld a = generateForest(o), b = generateForest(o);
  EXPECT_TRUE(sameObstacles(a.world, b.world));
  o.world.seed = 8;
  EXPECT_FALSE(sameObstacles(a.world, generateForest(o).world));
}

TEST(WorldGenerator, ForestTrunksCoverTheDensityFractionOfTheGround) {
  ForestOptions o;
  o.world.density = 0.05;
  const GeneratedWorld g = generateForest(o);
  double covered = 0;
  for (const auto& t : g.world.obstacles) {
    ASSERT_EQ(t.type, ObstacleType::Cylinder);
    EXPECT_GE(t.radius, 0.3);
    EXPECT_LE(t.radius, 0.6);
    EXPECT_NEAR(t.pos.z(), t.height / 2, 1e-12);  // standing on the ground
    covered += M_PI * t.radius * t.radius;
  }
  // 2500 m^2 x 0.05 = 125 m^2, from ~220 random radii: within 10 %.
  EXPECT_NEAR(covered / (50.0 * 50.0), 0.05, 0.005);
  EXPECT_GT(g.world.distanceToObstacles(g.start), 2.5 - 1e-9);
  EXPECT_GT(g.world.distanceToObstacles(g.goal), 2.5 - 1e-9);
}

TEST(WorldGenerator, ForestRejectsADensityAboveOneHalf) {
  ForestOptions o;
  o.world.density = 0.6;
  EXPECT_THROW(generateForest(o), InputError);
}

TEST(WorldGenerator, CityBuildsEveryLotAtDensityOneAndKeepsStreetsFree) {
  CityOptions o;
  o.world.density = 1.0;
  const GeneratedWorld g = generateCity(o);
  // 50 m wide, 4 m streets, 10 m pitch: floor(46 / 10) = 4 lots per axis.
  EXPECT_EQ(g.world.obstacles.size(), 16u);
  for (const auto& b : g.world.obstacles) {
    EXPECT_LE(b.size.x(), 6.0 + 1e-12);
    EXPECT_GE(b.size.z(), 2.0 - 1e-12);
    EXPECT_LE(b.size.z(), 10.0 + 1e-12);
  }
  // Along the first street from the start to below the goal, 2 m from every building.
  for (double x = g.start.x(); x <= g.goal.x(); x += 0.25)
    EXPECT_GE(g.world.distanceToObstacles({x, g.start.y(), g.start.z()}), 2.0 - 1e-9) << "x " << x;
  EXPECT_TRUE(connectedAtFlightHeight(g));
  o.world.density = 0.0;
  EXPECT_TRUE(generateCity(o).world.obstacles.empty());
}

TEST(WorldGenerator, CityLotOutcomesDoNotShiftWithDensity) {
  // Each lot draws the same values whether built or not: the buildings of a sparser city are a
  // subset, unchanged, of a denser one's with the same seed.
  CityOptions sparse, dense;
  sparse.world.density = 0.3;
  dense.world.density = 0.9;
  const auto a = generateCity(sparse).world.obstacles, b = generateCity(dense).world.obstacles;
  ASSERT_LT(a.size(), b.size());
  for (const auto& o : a) {
    bool found = false;
    for (const auto& p : b) found = found || (o.pos == p.pos && o.size == p.size);
    EXPECT_TRUE(found);
  }
}

TEST(WorldGenerator, MazeIsConnectedForEverySeedAndItsBoundsAreTheMaze) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    MazeWorldOptions o;
    o.world.size = {33, 27, 4};
    o.world.seed = seed;
    o.world.density = 1.0;
    const GeneratedWorld g = generateMazeWorld(o);
    EXPECT_EQ(g.world.bounds_max, Eigen::Vector3d(33, 27, 4));  // 11 x 9 cells of 3 m
    EXPECT_EQ(g.goal, Eigen::Vector3d(31.5, 25.5, 2));          // cell (10, 8)
    for (const auto& w : g.world.obstacles) EXPECT_DOUBLE_EQ(w.size.z(), 4.0);  // to the ceiling
    EXPECT_TRUE(connectedAtFlightHeight(g)) << "seed " << seed;
  }
}

TEST(WorldGenerator, MazeDensityKnocksOutWallsOnly) {
  MazeWorldOptions o;
  o.world.size = {45, 45, 4};
  double wall_area[2];
  for (int k = 0; k < 2; ++k) {
    o.world.density = k == 0 ? 1.0 : 0.5;
    double area = 0;
    for (const auto& w : generateMazeWorld(o).world.obstacles) area += w.size.x() * w.size.y();
    wall_area[k] = area;
  }
  // A 15 x 15 maze: 64 corridor cells joined by at least 63 carved cells of the 225, so at most
  // 98 wall cells of 9 m^2, and at least the 49 pillars (odd, odd) that are never carved.
  EXPECT_LE(wall_area[0], 98 * 9.0);
  EXPECT_GE(wall_area[0], 49 * 9.0);
  // Half of the inner walls between corridors knocked out leaves clearly less.
  EXPECT_LT(wall_area[1], wall_area[0] - 9.0 * 10);
}

// Options that would make more obstacles than a scenario may hold are refused before generating
// (a 10 km forest at density 0.5 would be 50 million trunks).
TEST(WorldGenerators, RefuseMoreObstaclesThanAScenarioMayHoldBeforeGenerating) {
  ForestOptions forest;
  forest.world.size = {10000, 10000, 10};
  forest.world.density = 0.5;
  try {
    generateForest(forest);
    FAIL() << "generated";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "generator forest");
    EXPECT_NE(e.problem().find("more than the 10000 a scenario may hold"), std::string::npos);
  }
  CityOptions city;
  city.world.size = {10000, 10000, 10};
  EXPECT_THROW(generateCity(city), InputError);
  MazeWorldOptions maze;
  maze.world.size = {10000, 10000, 10};
  EXPECT_THROW(generateMazeWorld(maze), InputError);
  forest.world.size = {50, 50, 10};  // the default world stays well inside
  EXPECT_GT(generateForest(forest).world.obstacles.size(), 100u);
}

}  // namespace
}  // namespace cosim
