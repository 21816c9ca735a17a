// A*, Dijkstra and Bellman-Ford must reproduce the optimal lengths of the MovingAI scenario
// files (8-connected, octile costs, no corner cutting) on every line checked here. The full
// check over every map of the benchmark set is `cosim grid-bench` (see the issue report).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "planning/grid/astar.h"
#include "planning/grid/bellman_ford.h"
#include "planning/grid/dijkstra.h"
#include "planning/grid/movingai.h"
#include "tests/support/movingai_files.h"

using namespace cosim;

namespace {

struct Case {
  const char* map;
  const char* scen;
  std::size_t astar_lines;       // lines checked with A* (0 = all)
  std::size_t uninformed_lines;  // lines checked with Dijkstra and Bellman-Ford (0 = all)
};

// The MAPF maps' scenario files in full; the 256x256 city map (CRLF, no final newline) in full
// for A* and its first 150 lines for the uninformed searches, which label most of the map on
// every query.
const Case kCases[] = {
    {"empty-8-8.map", "empty-8-8-random-1.scen", 0, 0},
    {"random-32-32-10.map", "random-32-32-10-random-1.scen", 0, 0},
    {"maze-32-32-2.map", "maze-32-32-2-random-1.scen", 0, 0},
    {"den312d.map", "den312d-even-1.scen", 0, 0},
    {"warehouse-10-20-10-2-1.map", "warehouse-10-20-10-2-1-even-1.scen", 0, 0},
    {"arena.map", "arena.map.scen", 0, 0},
    {"Berlin_0_256.map", "Berlin_0_256.map.scen", 0, 150},
};

GridQuery scenarioQuery(const OccupancyGrid& grid, const MovingAIScenarioLine& s) {
  GridQuery q;
  q.grid = &grid;
  q.start = {s.start_x, s.start_y, 0};
  q.goal = {s.goal_x, s.goal_y, 0};
  return q;
}

// Returns the number of lines checked; every mismatch is a test failure naming the line.
std::size_t checkScenario(GridPlanner& planner, const Case& c, std::size_t limit) {
  const OccupancyGrid grid = readMovingAIMap(test::movingAIFile(c.map));
  const auto lines = readMovingAIScenario(test::movingAIFile(c.scen));
  const std::size_t n = limit == 0 ? lines.size() : std::min(limit, lines.size());
  for (std::size_t i = 0; i < n; ++i) {
    const MovingAIScenarioLine& s = lines[i];
    const GridPlanResult r = planner.solveGrid(scenarioQuery(grid, s), StopToken::untimed());
    EXPECT_TRUE(r.success) << planner.name() << " " << c.scen << " line " << s.line << ": "
                           << r.message;
    EXPECT_NEAR(r.length, s.optimal_length, 1e-4 * std::max(1.0, s.optimal_length))
        << planner.name() << " " << c.scen << " line " << s.line;
    EXPECT_TRUE(matchesOptimalLength(s, r.length));
  }
  return n;
}

// All cases, with the line limits of A* or of the uninformed searches.
std::size_t checkAllCases(GridPlanner& planner, bool uninformed) {
  std::size_t checked = 0;
  for (const Case& c : kCases)
    checked += checkScenario(planner, c, uninformed ? c.uninformed_lines : c.astar_lines);
  return checked;
}

}  // namespace

TEST(GridMovingAIOptimality, AStarMatchesEveryScenarioLengthWithoutCornerCutting) {
  AStar astar;
  EXPECT_GT(checkAllCases(astar, false), 2000u);
}

TEST(GridMovingAIOptimality, DijkstraMatchesEveryScenarioLength) {
  Dijkstra dijkstra;
  EXPECT_GT(checkAllCases(dijkstra, true), 1000u);
}

TEST(GridMovingAIOptimality, BellmanFordMatchesEveryScenarioLength) {
  BellmanFord bellman_ford;
  EXPECT_GT(checkAllCases(bellman_ford, true), 1000u);
}

TEST(GridMovingAIOptimality, CornerCuttingMakesSomeBerlinPathsShorter) {
  // With corner cutting allowed the graph gains edges, so no length may grow and, on a city map
  // full of diagonal building corners, some must shrink below the published optimum.
  const std::string dir = COSIM_TEST_DATA_DIR "/movingai/";
  const OccupancyGrid grid = readMovingAIMap(dir + "Berlin_0_256.map");
  const auto lines = readMovingAIScenario(dir + "Berlin_0_256.map.scen");
  AStar cutting(AStar::Options{{8, true}, 1.0});
  int shorter = 0;
  for (std::size_t i = 0; i < 200; ++i) {
    const auto& s = lines[i];
    const GridPlanResult r = cutting.solveGrid(scenarioQuery(grid, s), StopToken::untimed());
    ASSERT_TRUE(r.success);
    EXPECT_LE(r.length, s.optimal_length + 1e-4 * s.optimal_length);
    if (r.length < s.optimal_length - 1e-3) ++shorter;
  }
  EXPECT_GT(shorter, 0);
}

TEST(GridMovingAIOptimality, TwoDecimalLengthsMatchWhenTheyRoundToThePrintedValue) {
  // bg512 files print lengths to 2 decimals: 16.2426 (= 12 + 3 sqrt 2) is printed 16.24.
  const auto old = parseMovingAIScenario("version 1.0\n0 a.map 20 20 0 0 15 3 16.24\n", "s");
  ASSERT_EQ(old.size(), 1u);
  EXPECT_EQ(old[0].optimal_decimals, 2);
  EXPECT_TRUE(matchesOptimalLength(old[0], 12 + 3 * std::sqrt(2.0)));
  EXPECT_FALSE(matchesOptimalLength(old[0], 16.2476));
  const auto current =
      parseMovingAIScenario("version 1\n0\ta.map\t20\t20\t0\t0\t15\t3\t16.24264069\n", "s");
  EXPECT_EQ(current[0].optimal_decimals, 8);
  EXPECT_TRUE(matchesOptimalLength(current[0], 12 + 3 * std::sqrt(2.0)));
  EXPECT_FALSE(matchesOptimalLength(current[0], 16.24));
}
