// Every multi-robot planner against the independent SolutionValidator, and CBS as the optimal
// reference (its sum of costs is never above another planner's on the same instance).
#include <gtest/gtest.h>

#include <queue>

#include "mapf_test_instances.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/maze_generator.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/reverse_resumable_astar.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/timed_paths.h"
#include "tests/support/movingai_files.h"

using namespace cosim;
using cosim::test::instanceFrom;

namespace {

const std::vector<std::string> kPlanners = {
    "independent_astar", "lra_star", "ca_star", "hca_star", "whca_star", "cbs", "lacam",
    "potential_field",   "pibt"};

MapfResult run(const std::string& planner, const MapfInstance& inst,
               const std::vector<std::pair<std::string, std::string>>& params = {},
               double time_limit_s = 5.0) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  auto algo = makeMapfPlanner(planner, p);
  MapfQuery q;
  q.instance = &inst;
  q.time_limit_s = time_limit_s;
  q.seed = 1;
  return algo->solve(q, StopToken::untimed());
}

// A MovingAI benchmark file by name, from wherever the repository keeps it.
std::string data(const std::string& name) {
  return test::movingAIFile(name);
}

// Agents on a seed-004 maze: starts on the first free cells of the top rows, goals on the last.
MapfInstance seedMazeInstance(int size, int agents, std::uint64_t seed) {
  MapfInstance inst;
  inst.grid = generateMaze(size, size, seed);
  std::vector<Cell> free_cells;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (inst.grid.free({x, y, 0})) free_cells.push_back({x, y, 0});
  for (int i = 0; i < agents; ++i) {
    inst.starts.push_back(free_cells[i * 7]);
    inst.goals.push_back(free_cells[free_cells.size() - 1 - i * 7]);
  }
  return inst;
}

struct NamedInstance {
  std::string name;
  MapfInstance instance;
};

std::vector<NamedInstance> testInstances() {
  std::vector<NamedInstance> v;
  v.push_back({"pocket corridor", test::pocketCorridor()});
  v.push_back({"2x2 crossing, 8-connected",
               instanceFrom({"..", ".."}, {{0, 0, 0}, {1, 0, 0}}, {{1, 1, 0}, {0, 1, 0}}, 8)});
  v.push_back({"random-32-32-10, 10 agents",
               readMovingAIMapfInstance(data("random-32-32-10.map"),
                                        data("random-32-32-10-random-1.scen"), 10)});
  v.push_back({"random-32-32-10, 10 agents, 8-connected",
               readMovingAIMapfInstance(data("random-32-32-10.map"),
                                        data("random-32-32-10-random-1.scen"), 10, 8)});
  v.push_back({"maze-32-32-2, 4 agents",
               readMovingAIMapfInstance(data("maze-32-32-2.map"),
                                        data("maze-32-32-2-random-1.scen"), 4)});
  v.push_back({"empty-8-8, 8 agents, 8-connected",
               readMovingAIMapfInstance(data("empty-8-8.map"),
                                        data("empty-8-8-random-1.scen"), 8, 8)});
  v.push_back({"seed-004 maze 15x15, 4 agents", seedMazeInstance(15, 4, 5)});
  return v;
}

}  // namespace

TEST(MapfPlanners, EverySolutionReturnedPassesTheValidatorAndCbsIsNeverWorse) {
  int successes = 0;
  for (const auto& [name, inst] : testInstances()) {
    const MapfResult cbs = run("cbs", inst);
    ASSERT_TRUE(cbs.success) << name << ": " << cbs.message;
    ASSERT_TRUE(validateMapfSolution(inst, cbs.paths).valid()) << name;
    for (const auto& planner : kPlanners) {
      // LaCAM*'s default anytime phase is about a second per instance; a shorter one here.
      const MapfResult r = planner == "lacam" ? run(planner, inst, {{"refine_iterations", "20000"}})
                                              : run(planner, inst);
      if (!r.success) continue;
      ++successes;
      const MapfValidation v = validateMapfSolution(inst, r.paths);
      EXPECT_TRUE(v.valid()) << planner << " on " << name << ": " << v.conflicts.size()
                             << " conflicts, " << v.problems.size() << " problems";
      EXPECT_LE(sumOfCosts(cbs.paths), sumOfCosts(r.paths)) << planner << " on " << name;
    }
  }
  // Most planners solve most of these small instances.
  EXPECT_GE(successes, 30);
}

TEST(MapfPlanners, CbsFindsTheOptimumOfThePocketCorridor) {
  const MapfResult r = run("cbs", test::pocketCorridor());
  ASSERT_TRUE(r.success);
  EXPECT_EQ(sumOfCosts(r.paths), 12);
  EXPECT_EQ(makespan(r.paths), 7);
}

TEST(MapfPlanners, CbsOptimumOfCrossingAgentsDependsOnConnectivity) {
  // 8-connected: both diagonals would cross at the block centre, so one agent spends one more
  // step (1 + 2); 4-connected: both need two steps and can follow each other round (2 + 2).
  const std::vector<std::string> rows = {"..", ".."};
  const std::vector<Cell> s = {{0, 0, 0}, {1, 0, 0}}, g = {{1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(sumOfCosts(run("cbs", instanceFrom(rows, s, g, 8)).paths), 3);
  EXPECT_EQ(sumOfCosts(run("cbs", instanceFrom(rows, s, g, 4)).paths), 4);
}

TEST(MapfPlanners, IndependentAStarReportsTheSwapConflictAsFailure) {
  const MapfResult r = run("independent_astar", test::pocketCorridor());
  EXPECT_FALSE(r.success);
  const MapfValidation v = validateMapfSolution(test::pocketCorridor(), r.paths);
  ASSERT_FALSE(v.conflicts.empty());
  EXPECT_EQ(v.conflicts[0].kind, MapfConflict::Kind::kSwap);
}

TEST(MapfPlanners, DynamicPrioritiesSolveThePocketCorridorTheFixedOrderCannot) {
  // In the fixed order agent 0 takes its straight path first and agent 1 has no escape (seed 004
  // Fig. 2.3: prioritised planning is incomplete). Raising agent 1 after its failure (seed 004
  // §4.5) lets agent 0 duck into the pocket: the optimum, after one restart.
  const auto inst = test::pocketCorridor();
  for (const auto& planner : {"ca_star", "hca_star"}) {
    EXPECT_FALSE(run(planner, inst).success) << planner;
    const MapfResult r = run(planner, inst, {{"priorities", "dynamic"}});
    ASSERT_TRUE(r.success) << planner << ": " << r.message;
    EXPECT_TRUE(validateMapfSolution(inst, r.paths).valid());
    EXPECT_EQ(r.counters.at("restarts"), 1);
    EXPECT_EQ(sumOfCosts(r.paths), 12);
  }
  EXPECT_FALSE(run("whca_star", inst, {{"priorities", "fixed"}}).success);
}

TEST(MapfPlanners, WhcaStarWithDynamicPrioritiesSolvesTheMazeWhereFixedOnesLivelock) {
  // Seed 004 claim (§4.5, §6.3): raising the priority of blocked agents raises the success rate.
  const auto inst = readMovingAIMapfInstance(data("maze-32-32-2.map"),
                                             data("maze-32-32-2-random-1.scen"), 20);
  const MapfResult fixed = run("whca_star", inst, {{"priorities", "fixed"}});
  EXPECT_FALSE(fixed.success);
  const MapfResult dynamic = run("whca_star", inst, {{"priorities", "dynamic"}});
  ASSERT_TRUE(dynamic.success) << dynamic.message;
  EXPECT_TRUE(validateMapfSolution(inst, dynamic.paths).valid());
}

TEST(MapfPlanners, WhcaStarPlansTwentyAgentsOnRandom32) {
  const auto inst = readMovingAIMapfInstance(data("random-32-32-10.map"),
                                             data("random-32-32-10-random-1.scen"), 20);
  const MapfResult r = run("whca_star", inst, {{"window", "8"}});
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(validateMapfSolution(inst, r.paths).valid());
  const MapfResult cbs = run("cbs", inst);
  ASSERT_TRUE(cbs.success);
  EXPECT_GE(sumOfCosts(r.paths), sumOfCosts(cbs.paths));
}

TEST(MapfPlanners, UnreachableGoalIsReportedNotSearchedForEver) {
  const auto inst = instanceFrom({"..@.."}, {{0, 0, 0}}, {{4, 0, 0}});
  for (const auto& planner : kPlanners) {
    const MapfResult r = run(planner, inst, {}, 2.0);
    EXPECT_FALSE(r.success) << planner;
    EXPECT_LT(r.time_ms, 1500.0) << planner;
  }
}

TEST(MapfPlanners, LraStarIsDeterministicInTheSeed) {
  const auto inst = readMovingAIMapfInstance(data("empty-8-8.map"),
                                             data("empty-8-8-random-1.scen"), 12);
  const MapfResult a = run("lra_star", inst), b = run("lra_star", inst);
  ASSERT_EQ(a.paths.size(), b.paths.size());
  for (std::size_t i = 0; i < a.paths.size(); ++i) EXPECT_EQ(a.paths[i], b.paths[i]);
}

TEST(MapfPlanners, PotentialFieldGetsStuckInAMazeButNotInOpenSpace) {
  // Seed 004 §4.6: "it did not work out, because of local minima".
  const MapfResult maze = run("potential_field", seedMazeInstance(15, 4, 5));
  EXPECT_FALSE(maze.success);
  const auto open = instanceFrom({"......", "......", "......", "......"}, {{0, 0, 0}, {0, 3, 0}},
                                 {{5, 3, 0}, {5, 0, 0}});
  const MapfResult r = run("potential_field", open);
  ASSERT_TRUE(r.success) << r.message;
  EXPECT_TRUE(validateMapfSolution(open, r.paths).valid());
}

TEST(MapfPlannerRegistry, KnowsTheContractNamesAndRejectsUnknownOnes) {
  for (const auto& name : kPlanners) {
    ParamSet p("test");
    EXPECT_EQ(makeMapfPlanner(name, p)->name(), name);
  }
  ParamSet p("test");
  EXPECT_THROW(makeMapfPlanner("astar", p), InputError);
  ParamSet misspelt("test");
  misspelt.set("windw", "4");
  EXPECT_THROW(makeMapfPlanner("whca_star", misspelt), InputError);
}

TEST(MovingAIMapfInstance, MoreAgentsThanScenarioLinesIsAnInputError) {
  EXPECT_THROW(readMovingAIMapfInstance(data("empty-8-8.map"),
                                        data("empty-8-8-random-1.scen"), 1000),
               InputError);
}

TEST(ReverseResumableAStar, DistancesEqualBreadthFirstSearch) {
  const OccupancyGrid g = readMovingAIMap(data("random-32-32-10.map"));
  const MapfGrid grid(g, 4);
  const int goal = grid.id({3, 4, 0});
  ReverseResumableAStar rra(grid, goal, grid.id({30, 30, 0}));
  std::vector<int> bfs(grid.cellCount(), GoalDistance::kUnreachable);
  std::queue<int> q;
  bfs[goal] = 0;
  q.push(goal);
  while (!q.empty()) {
    const int c = q.front();
    q.pop();
    for (const int n : grid.neighbours(c))
      if (bfs[n] == GoalDistance::kUnreachable) bfs[n] = bfs[c] + 1, q.push(n);
  }
  int compared = 0;
  for (int c = 0; c < grid.cellCount(); ++c)
    if (grid.free(c)) {
      EXPECT_EQ(rra.distance(c), bfs[c]) << c;
      ++compared;
    }
  EXPECT_EQ(compared, 1024 - static_cast<int>(g.blockedCount()));
}

TEST(TimedMetricPaths, CellCentresAtMultiplesOfTheStepDuration) {
  OccupancyGrid g(4, 4, 1, 0.5, Eigen::Vector3d(10.0, 20.0, 0.0));
  const auto timed = timedMetricPaths(g, {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}}, 2.0, 0.1);
  ASSERT_EQ(timed[0].size(), 3u);
  EXPECT_DOUBLE_EQ(timed[0][2].t, 4.0);
  EXPECT_DOUBLE_EQ(timed[0][2].position.x(), 10.75);
  EXPECT_DOUBLE_EQ(timed[0][2].position.y(), 20.75);
  EXPECT_DOUBLE_EQ(timed[0][2].position.z(), 0.1);
}
