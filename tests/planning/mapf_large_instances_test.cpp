// LaCAM* and PIBT at the benchmark's scale: 1000 agents on a generated map the size of the
// MovingAI benchmark's brc202d (481 x 530 cells), and every bundled benchmark map of
// experiments/maps at its scenario's full agent count, each solution accepted by the
// independent validator. The memory guard accepts them by what the lazy distance tables need
// (a full per-agent table, agents x cells, would refuse the large map), and the tables hold
// only what their searches reached.
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include "planning/mapf/mapf_memory_estimate.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/movingai_instance.h"
#include "planning/mapf/solution_validator.h"
#include "planning/mapf/split_mix64.h"

using namespace cosim;

namespace {

// Rooms of 16 x 16 cells behind one-cell walls, a door three cells wide in every wall at a
// random place, and one cell in ten of each room blocked at random: long detours, as in a
// game map, on 481 x 530 = 254 930 cells. Starts and goals: distinct random free cells of the
// part the first room reaches.
MapfInstance roomsMap(int agents, std::uint64_t seed) {
  constexpr int kNx = 481, kNy = 530, kRoom = 17;
  SplitMix64 rng(seed);
  MapfInstance inst;
  inst.grid = OccupancyGrid(kNx, kNy);
  for (int y = 0; y < kNy; ++y)
    for (int x = 0; x < kNx; ++x)
      if (x % kRoom == 0 || y % kRoom == 0 || rng.below(10) == 0)
        inst.grid.setBlocked({x, y, 0}, true);
  for (int ry = 0; ry * kRoom < kNy; ++ry)
    for (int rx = 0; rx * kRoom < kNx; ++rx) {
      const int door_x = rx * kRoom + 1 + static_cast<int>(rng.below(kRoom - 4));
      const int door_y = ry * kRoom + 1 + static_cast<int>(rng.below(kRoom - 4));
      for (int k = 0; k < 3; ++k)
        for (int d = -1; d <= 1; ++d) {  // the wall and the cells on both sides of the door
          if (inst.grid.inside(door_x + k, ry * kRoom + d))
            inst.grid.setBlocked({door_x + k, ry * kRoom + d, 0}, false);
          if (inst.grid.inside(rx * kRoom + d, door_y + k))
            inst.grid.setBlocked({rx * kRoom + d, door_y + k, 0}, false);
        }
    }
  // The part reachable from the first free cell, by breadth-first search.
  std::vector<char> reached(static_cast<std::size_t>(kNx) * kNy, 0);
  std::vector<Cell> part, queue = {{1, 1, 0}};
  inst.grid.setBlocked({1, 1, 0}, false);
  reached[inst.grid.index(1, 1)] = 1;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const Cell c = queue[k];
    for (const Cell& w : {Cell{c.x - 1, c.y, 0}, Cell{c.x + 1, c.y, 0}, Cell{c.x, c.y - 1, 0},
                          Cell{c.x, c.y + 1, 0}})
      if (inst.grid.free(w) && !reached[inst.grid.index(w)])
        reached[inst.grid.index(w)] = 1, queue.push_back(w);
  }
  std::vector<char> start_taken(reached.size(), 0), goal_taken(reached.size(), 0);
  const auto pick = [&](std::vector<char>& taken) {
    for (;;) {
      const Cell c = queue[rng.below(static_cast<std::uint32_t>(queue.size()))];
      if (!taken[inst.grid.index(c)]) return taken[inst.grid.index(c)] = 1, c;
    }
  };
  for (int i = 0; i < agents; ++i) {
    inst.starts.push_back(pick(start_taken));
    inst.goals.push_back(pick(goal_taken));
  }
  return inst;
}

MapfResult solve(const std::string& planner, const MapfInstance& inst) {
  ParamSet p("test");
  if (planner == "lacam") p.set("anytime", "false");
  auto algo = makeMapfPlanner(planner, p);
  MapfQuery q;
  q.instance = &inst;
  q.time_limit_s = 60.0;
  return algo->solve(q, StopToken::untimed());
}

void expectSolved(const MapfInstance& inst, const MapfResult& r, const std::string& what) {
  ASSERT_TRUE(r.success) << what << ": " << r.message;
  const MapfValidation v = validateMapfSolution(inst, r.paths);
  EXPECT_TRUE(v.valid()) << what << ": " << v.conflicts.size() << " conflicts, "
                         << (v.problems.empty() ? "" : v.problems.front());
  EXPECT_EQ(r.paths.size(), inst.starts.size()) << what;
}

TEST(MapfAtScale, ThousandAgentsOnABrc202dSizedMapWithinTheMemoryGuard) {
  const MapfInstance inst = roomsMap(1000, 7);
  checkMapfInstance(inst, "rooms");
  // Agents x cells is 254 930 000 (2.5 times the former limit); the tables' own measure, a
  // 16-bit row of free cells per goal, is well under the gigabyte allowed.
  const MapfMemoryEstimate need = estimateMapfTableMemory(inst, "lacam");
  EXPECT_LT(need.bytes, 0.5 * kMaxMapfTableBytes) << need.breakdown;
  EXPECT_NE(need.breakdown.find("x 2 bytes"), std::string::npos) << need.breakdown;
  EXPECT_NO_THROW(checkMapfTableMemory(inst, "lacam", "rooms"));
  for (const std::string planner : {"lacam", "pibt"}) {
    const MapfResult r = solve(planner, inst);
    expectSolved(inst, r, planner);
    // Lazy tables: what the searches wrote is below the worst case the guard counted.
    EXPECT_LT(r.counters.at("distance_table_mb") * (1 << 20), need.bytes) << planner;
  }
}

TEST(MapfAtScale, EveryBundledBenchmarkMapAtItsFullScenarioCount) {
  // maze-32-32-2 (333) and warehouse (1000) are in mapf_lacam_test.cpp.
  for (const auto& [name, agents] :
       std::vector<std::tuple<std::string, int>>{{"den312d", 1000},
                                                 {"empty-32-32", 512},
                                                 {"random-32-32-10", 461},
                                                 {"empty-16-16", 128},
                                                 {"empty-8-8", 32}}) {
    const std::string dir = COSIM_SOURCE_DIR "/experiments/maps/";
    const MapfInstance inst =
        readMovingAIMapfInstance(dir + name + ".map", dir + name + "-random-1.scen", agents, 4);
    expectSolved(inst, solve("lacam", inst), name);
  }
}

}  // namespace
