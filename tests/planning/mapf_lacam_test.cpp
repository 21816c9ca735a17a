// LaCAM* (lacam) and PIBT (pibt): CBS's optimum reached by the anytime search, solutions the
// independent validator accepts on 4- and 8-connected benchmark maps and on 3D grids, the full
// scenario of dense benchmark maps, determinism in the seed, and the time limit and stop flag.
#include <gtest/gtest.h>

#include <atomic>

#include "mapf_test_instances.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_graph.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "tests/support/movingai_files.h"

using namespace cosim;
using cosim::test::instanceFrom;

namespace {

MapfResult run(const std::string& planner, const MapfInstance& inst,
               const std::vector<std::pair<std::string, std::string>>& params = {},
               double time_limit_s = 30.0, std::uint64_t seed = 1,
               const std::atomic<bool>* stop = nullptr) {
  ParamSet p("test");
  for (const auto& [k, v] : params) p.set(k, v);
  auto algo = makeMapfPlanner(planner, p);
  MapfQuery q;
  q.instance = &inst;
  q.time_limit_s = time_limit_s;
  q.seed = seed;
  return algo->solve(q, StopToken::untimed(stop));
}

// A MovingAI benchmark file by name, from wherever the repository keeps it.
std::string data(const std::string& name) {
  return test::movingAIFile(name);
}

MapfInstance benchmark(const std::string& map, const std::string& scen, int agents,
                       int connectivity = 4) {
  return readMovingAIMapfInstance(data(map), data(scen), agents, connectivity);
}

// A free nx x ny x nz grid.
MapfInstance openBox(int nx, int ny, int nz, std::vector<Cell> starts, std::vector<Cell> goals,
                     int connectivity) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(nx, ny, nz);
  inst.connectivity = connectivity;
  inst.starts = std::move(starts);
  inst.goals = std::move(goals);
  return inst;
}

void expectValid(const MapfInstance& inst, const MapfResult& r, const std::string& what) {
  ASSERT_TRUE(r.success) << what << ": " << r.message;
  const MapfValidation v = validateMapfSolution(inst, r.paths);
  EXPECT_TRUE(v.valid()) << what << ": " << v.conflicts.size() << " conflicts, "
                         << (v.problems.empty() ? "" : v.problems.front());
}

}  // namespace

TEST(Lacam, AnytimeSearchImprovesItsFirstSolutionDownToTheCbsOptimum) {
  // Measured: the first solutions cost 218 and 78; the search then proves the CBS optimum.
  for (const auto& inst :
       {benchmark("random-32-32-10.map", "random-32-32-10-random-1.scen", 8),
        benchmark("empty-8-8.map", "empty-8-8-random-1.scen", 12)}) {
    const MapfResult cbs = run("cbs", inst);
    ASSERT_TRUE(cbs.success);
    const MapfResult r = run("lacam", inst);
    expectValid(inst, r, "lacam");
    EXPECT_EQ(sumOfCosts(r.paths), sumOfCosts(cbs.paths));
    EXPECT_GT(r.counters.at("first_sum_of_costs"), static_cast<double>(sumOfCosts(r.paths)));
    EXPECT_GE(r.counters.at("improvements"), 1.0);
    EXPECT_EQ(r.counters.at("proven_optimal"), 1.0);
    EXPECT_EQ(r.counters.at("anytime_cut_by_time"), 0.0);
    // The sum of loss it minimises equals the sum of costs here: no agent leaves its goal.
    EXPECT_EQ(r.counters.at("final_sum_of_loss"), static_cast<double>(sumOfCosts(cbs.paths)));
  }
}

TEST(Lacam, WithoutAnytimeItKeepsTheFirstSolution) {
  const auto inst =
      benchmark("random-32-32-10.map", "random-32-32-10-random-1.scen", 8);
  const MapfResult r = run("lacam", inst, {{"anytime", "false"}});
  expectValid(inst, r, "lacam, anytime=false");
  EXPECT_EQ(static_cast<double>(sumOfCosts(r.paths)), r.counters.at("first_sum_of_costs"));
  EXPECT_EQ(sumOfCosts(r.paths), 218);
  EXPECT_EQ(r.counters.at("proven_optimal"), 0.0);
}

TEST(Lacam, ReachesTheOptimumOnFourAndEightConnectedGrids) {
  // 2x2 block, agents from the top corners to the opposite bottom ones: 8-connected both
  // diagonals would cross at the centre, so one takes a step more (1 + 2); 4-connected 2 + 2.
  const std::vector<std::string> block = {"..", ".."};
  const std::vector<Cell> s = {{0, 0, 0}, {1, 0, 0}}, g = {{1, 1, 0}, {0, 1, 0}};
  EXPECT_EQ(sumOfCosts(run("lacam", instanceFrom(block, s, g, 8)).paths), 3);
  EXPECT_EQ(sumOfCosts(run("lacam", instanceFrom(block, s, g, 4)).paths), 4);
  // The pocket corridor: one agent ducks into the pocket (CBS's 12).
  const MapfResult pocket = run("lacam", test::pocketCorridor());
  expectValid(test::pocketCorridor(), pocket, "pocket corridor");
  EXPECT_EQ(sumOfCosts(pocket.paths), 12);
  for (const int connectivity : {4, 8}) {
    const auto inst =
        benchmark("empty-8-8.map", "empty-8-8-random-1.scen", 6, connectivity);
    // 8-connected the first solution is already optimal, but proving it takes long: a short
    // anytime phase keeps the test fast.
    const MapfResult cbs = run("cbs", inst), pibt = run("pibt", inst),
                     lacam = run("lacam", inst, {{"refine_iterations", "20000"}});
    expectValid(inst, lacam, "lacam");
    expectValid(inst, pibt, "pibt");
    EXPECT_EQ(sumOfCosts(lacam.paths), sumOfCosts(cbs.paths)) << connectivity;
    EXPECT_GE(sumOfCosts(pibt.paths), sumOfCosts(cbs.paths)) << connectivity;
  }
}

TEST(Lacam, SolvesTheFullScenarioOfDenseBenchmarkMaps) {
  // The benchmark files' full agent counts: 333 agents in a maze of corridors two cells wide,
  // 1000 in the warehouse, 290 in den312d (the full count of its even-1 file).
  for (const auto& [map, scen, agents] : std::vector<std::tuple<std::string, std::string, int>>{
           {"maze-32-32-2.map", "maze-32-32-2-random-1.scen", 333},
           {"warehouse-10-20-10-2-1.map", "warehouse-10-20-10-2-1-random-1.scen", 1000},
           {"den312d.map", "den312d-even-1.scen", 290}}) {
    const auto inst = benchmark(map, scen, agents);
    const MapfResult r = run("lacam", inst, {{"anytime", "false"}}, 60.0);
    expectValid(inst, r, map);
  }
}

TEST(Lacam, SameSeedSamePathsAnotherSeedOtherPaths) {
  const auto inst =
      benchmark("random-32-32-10.map", "random-32-32-10-random-1.scen", 150);
  for (const std::string planner : {"lacam", "pibt"}) {
    const std::vector<std::pair<std::string, std::string>> params =
        planner == "lacam"
            ? std::vector<std::pair<std::string, std::string>>{{"refine_iterations", "300"}}
            : std::vector<std::pair<std::string, std::string>>{};
    const MapfResult a = run(planner, inst, params, 30.0, 7),
                     b = run(planner, inst, params, 30.0, 7);
    const MapfResult c = run(planner, inst, params, 30.0, 8);
    expectValid(inst, a, planner);
    EXPECT_EQ(a.paths, b.paths) << planner;
    EXPECT_NE(a.paths, c.paths) << planner;  // the seed breaks PIBT's ties
  }
}

TEST(Lacam, TinyTimeLimitEndsTheSearchWithATimeLimitMessage) {
  // 1000 agents and 1 ms: not even the distance tables are done. The bound below is loose (it
  // only fails if the limit were ignored: the full search takes seconds).
  const auto inst = benchmark("warehouse-10-20-10-2-1.map",
                              "warehouse-10-20-10-2-1-random-1.scen", 1000);
  for (const std::string planner : {"lacam", "pibt"}) {
    const MapfResult r = run(planner, inst, {}, 0.001);
    EXPECT_FALSE(r.success) << planner;
    EXPECT_EQ(r.message, "time limit reached") << planner;
    EXPECT_LT(r.time_ms, 500.0) << planner;
  }
}

TEST(MapfPlanners, EveryPlannerStopsAtOnceWhenAskedTo) {
  const auto inst =
      benchmark("random-32-32-10.map", "random-32-32-10-random-1.scen", 100);
  const std::atomic<bool> stop{true};
  for (const auto& e : mapfPlanners()) {
    const MapfResult r = run(e.name, inst, {}, 30.0, 1, &stop);
    EXPECT_FALSE(r.success) << e.name;
  }
  EXPECT_EQ(run("lacam", inst, {}, 30.0, 1, &stop).message, "stopped");
}

TEST(Lacam, PlansOnThreeDimensionalGrids) {
  // Two agents exchange opposite corners of a free 3x3x3 cube. 6-connected: 6 steps each, room
  // to pass. 26-connected: the only 2-step way runs through the centre, which both cannot use
  // (vertex or swap conflict), so one takes 3 steps. 18-connected (at most two coordinates per
  // step): 3 steps each, and there are disjoint ways.
  const std::vector<Cell> s = {{0, 0, 0}, {2, 2, 2}}, g = {{2, 2, 2}, {0, 0, 0}};
  for (const auto& [connectivity, optimum] :
       std::vector<std::pair<int, long>>{{6, 12}, {18, 6}, {26, 5}}) {
    const auto inst = openBox(3, 3, 3, s, g, connectivity);
    for (const std::string planner : {"lacam", "pibt"}) {
      const MapfResult r = run(planner, inst);
      expectValid(inst, r, planner + " " + std::to_string(connectivity));
      if (planner == "lacam") {
        EXPECT_EQ(sumOfCosts(r.paths), optimum) << connectivity;
        EXPECT_EQ(r.counters.at("proven_optimal"), 1.0) << connectivity;
      }
    }
  }
  // A crowded two-storey grid with a wall on each floor: twelve agents rotate their places.
  MapfInstance crowd;
  crowd.grid = OccupancyGrid(6, 4, 2);
  for (int y = 0; y < 3; ++y)
    crowd.grid.setBlocked(3, y, 0, true), crowd.grid.setBlocked(2, y + 1, 1, true);
  std::vector<Cell> cells;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 6; ++x)
        if (crowd.grid.free({x, y, z})) cells.push_back({x, y, z});
  for (int i = 0; i < 12; ++i) {
    crowd.starts.push_back(cells[i]);
    crowd.goals.push_back(cells[cells.size() - 1 - i]);
  }
  crowd.connectivity = 6;
  checkMapfInstance(crowd, "test");
  expectValid(crowd, run("lacam", crowd, {{"refine_iterations", "20000"}}), "crowded two storeys");
}

TEST(MapfGraph, MovesAndConflictKeysOfTwoAndThreeDimensionalGrids) {
  const OccupancyGrid open2(3, 3), open3(3, 3, 3);
  const Cell centre2{1, 1, 0}, centre3{1, 1, 1};
  for (const auto& [connectivity, degree] : std::vector<std::pair<int, int>>{{4, 4}, {8, 8}}) {
    const MapfGraph g = MapfGraph::fromGrid(open2, connectivity);
    EXPECT_EQ(g.degree(g.vertexOf(centre2)), degree);
  }
  for (const auto& [connectivity, degree] :
       std::vector<std::pair<int, int>>{{6, 6}, {18, 18}, {26, 26}}) {
    const MapfGraph g = MapfGraph::fromGrid(open3, connectivity);
    EXPECT_EQ(g.degree(g.vertexOf(centre3)), degree);
  }
  // The key of a move: a swap shares it, crossing diagonals share it, neighbouring edges do not.
  const MapfGraph g = MapfGraph::fromGrid(open2, 8);
  const auto key = [&g](const Cell& a, const Cell& b) {
    const int u = g.vertexOf(a), v = g.vertexOf(b);
    for (std::size_t k = 0; k < g.neighbours(u).size(); ++k)
      if (g.neighbours(u)[k] == v) return static_cast<long>(g.moveKeys(u)[k]);
    return -1L;
  };
  EXPECT_EQ(key({0, 0, 0}, {1, 0, 0}), key({1, 0, 0}, {0, 0, 0}));
  EXPECT_EQ(key({0, 0, 0}, {1, 1, 0}), key({1, 0, 0}, {0, 1, 0}));
  EXPECT_NE(key({0, 0, 0}, {1, 0, 0}), key({0, 0, 0}, {0, 1, 0}));
  EXPECT_NE(key({0, 0, 0}, {1, 1, 0}), key({1, 1, 0}, {2, 2, 0}));
  // No corner cutting: beside a blocked cell the diagonal past it is not a move.
  OccupancyGrid walled(2, 2);
  walled.setBlocked(1, 0, 0, true);
  const MapfGraph w = MapfGraph::fromGrid(walled, 8);
  EXPECT_EQ(w.degree(w.vertexOf({0, 0, 0})), 1);
  EXPECT_THROW(MapfGraph::fromGrid(open2, 6), InputError);
  EXPECT_THROW(MapfGraph::fromGrid(open3, 8), InputError);
}

TEST(Pibt, SwapLetsTwoAgentsPassInACorridorThatPlainPibtCannot) {
  // The pocket corridor: the agents meet head on; one must back into the side pocket. Without
  // the swap technique (IJCAI 2023 §4) PIBT pushes the other back and forth for ever; with it
  // the optimum (CBS's 12).
  const auto inst = test::pocketCorridor();
  const MapfResult with_swap = run("pibt", inst);
  expectValid(inst, with_swap, "pibt with swap");
  EXPECT_EQ(sumOfCosts(with_swap.paths), 12);
  const MapfResult without = run("pibt", inst, {{"swap", "false"}});
  EXPECT_FALSE(without.success);
  EXPECT_EQ(without.message, "not all agents arrived within 1000 steps");
}
