#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "sim/scenario.h"

using namespace cosim;

namespace {

const char* kGood = R"(world:
  bounds: {min: [0, 0, 0], max: [20, 20, 8]}
  obstacles:
    - {type: box, pos: [10, 10, 2.5], size: [4, 2, 5], yaw: 30}
    - {type: cylinder, pos: [5, 15, 3], radius: 1.0, height: 6}
    - {type: sphere, pos: [15, 5, 4], radius: 1.5}
vehicles:
  - name: uav1
    model: quad_1500g
    start: [2, 2, 2]
    goal: [18, 18, 4]
planner: {name: astar, resolution: 0.5, margin: 0.25}
sim: {timestep: 0.001, control_rate: 500, max_time: 60, seed: 7}
)";

// Parses `text` and returns the InputError's place (fails the test if none is thrown).
std::string placeOfError(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    parseScenario(text, "s.yaml", sets);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), sets.empty() || e.file() != "command line" ? "s.yaml" : "command line");
    return e.place() + " | " + e.problem();
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST(ScenarioLoader, ReadsEverySection) {
  const Scenario s = parseScenario(kGood, "s.yaml");
  ASSERT_EQ(s.world.obstacles.size(), 3u);
  EXPECT_EQ(s.world.obstacles[0].type, ObstacleType::Box);
  EXPECT_DOUBLE_EQ(s.world.obstacles[0].yaw_deg, 30.0);
  EXPECT_DOUBLE_EQ(s.world.obstacles[1].height, 6.0);
  EXPECT_EQ(s.vehicles[0].goal(), Eigen::Vector3d(18, 18, 4));
  EXPECT_EQ(s.motion.planner.name, "astar");
  EXPECT_DOUBLE_EQ(s.motion.planner.margin, 0.25);
  EXPECT_TRUE(s.motion.planner.params.has("resolution"));
  EXPECT_FALSE(s.motion.planner.params.has("margin"));
  EXPECT_EQ(s.sim.seed, 7u);
}

TEST(ScenarioLoader, SetOverridesApplyBeforeValidation) {
  const Scenario s = parseScenario(kGood, "s.yaml", {"planner.name=theta_star", "sim.seed=3"});
  EXPECT_EQ(s.motion.planner.name, "theta_star");
  EXPECT_EQ(s.sim.seed, 3u);
}

TEST(ScenarioLoader, UnknownKeyNamesLineAndKey) {
  const std::string e = placeOfError(replace(kGood, "sim: {", "sim: {colour: red, "));
  EXPECT_NE(e.find("line 13, key sim.colour"), std::string::npos) << e;
}

TEST(ScenarioLoader, MalformedYamlNamesTheLine) {
  const std::string e = placeOfError("world:\n  bounds: {min: [0, 0, 0]\n");
  EXPECT_NE(e.find("line"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed YAML"), std::string::npos) << e;
}

TEST(ScenarioLoader, WrongTypeIsRejected) {
  const std::string e = placeOfError(replace(kGood, "radius: 1.0", "radius: wide"));
  EXPECT_NE(e.find("world.obstacles[1].radius"), std::string::npos) << e;
  EXPECT_NE(e.find("must be a number"), std::string::npos) << e;
}

TEST(ScenarioLoader, NegativeSizeIsRejected) {
  const std::string e = placeOfError(replace(kGood, "size: [4, 2, 5]", "size: [4, -2, 5]"));
  EXPECT_NE(e.find("line 4, key world.obstacles[0].size"), std::string::npos) << e;
}

TEST(ScenarioLoader, StartInsideAnObstacleIsRejected) {
  const std::string e = placeOfError(replace(kGood, "start: [2, 2, 2]", "start: [15, 5, 4]"));
  EXPECT_NE(e.find("vehicles[0].start"), std::string::npos) << e;
  EXPECT_NE(e.find("inside world.obstacles[2] (obstacles are numbered from 0"), std::string::npos)
      << e;  // one numbering, the one --set uses
}

TEST(ScenarioLoader, GoalOutsideBoundsIsRejected) {
  const std::string e = placeOfError(replace(kGood, "goal: [18, 18, 4]", "goal: [18, 25, 4]"));
  EXPECT_NE(e.find("line 11, key vehicles[0].goal"), std::string::npos) << e;
  EXPECT_NE(e.find("outside the world bounds"), std::string::npos) << e;
}

TEST(ScenarioLoader, UnknownModelIsRejected) {
  const std::string e = placeOfError(replace(kGood, "model: quad_1500g", "model: quad_9000"));
  EXPECT_NE(e.find("vehicles[0].model"), std::string::npos) << e;
}

TEST(ScenarioLoader, ControlRateMustDivideThePhysicsRate) {
  const std::string e = placeOfError(replace(kGood, "control_rate: 500", "control_rate: 300"));
  EXPECT_NE(e.find("sim.control_rate"), std::string::npos) << e;
}

TEST(ScenarioLoader, MissingWorldIsRejected) {
  const std::string e = placeOfError("vehicles: []\n");
  EXPECT_NE(e.find("world"), std::string::npos) << e;
}

TEST(ScenarioLoader, MalformedSetOverrideIsRejected) {
  EXPECT_THROW(parseScenario(kGood, "s.yaml", {"planner.name"}), InputError);
}

TEST(ScenarioLoader, NonFiniteNumberIsRejected) {
  const std::string e = placeOfError(replace(kGood, "max_time: 60", "max_time: .nan"));
  EXPECT_NE(e.find("sim.max_time"), std::string::npos) << e;
}

// world.grid_map: a MovingAI map as the world (seed 004's grid worlds).
namespace {
std::string gridMapScenario(const std::string& grid_map, const std::string& extra_world = "") {
  return "world:\n  grid_map: " + grid_map + "\n" + extra_world +
         "vehicles: [{name: r0, model: omni_base, start: [0.25, 0.25, 0], goal: [3.75, 3.75, "
         "0]}]\n";
}
const std::string kEightByEight = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map";
}  // namespace

TEST(ScenarioLoader, GridMapBecomesTheWorldWithTheUsersBlockedCells) {
  const Scenario s =
      parseScenario(gridMapScenario("{file: " + kEightByEight +
                                    ", cell: 0.5, height: 0.4, blocked: [[3, 3], [4, 3]]}"),
                    "s.yaml");
  ASSERT_TRUE(s.grid_map.present());
  EXPECT_EQ(s.world.bounds_max, Eigen::Vector3d(4.0, 4.0, 3.0));
  EXPECT_EQ(s.grid_map.grid.blockedCount(), 2u);
  EXPECT_TRUE(s.grid_map.grid.blocked(4, 3));
  // Two neighbouring cells: one box 1 m x 0.5 m, centred between them.
  ASSERT_EQ(s.world.obstacles.size(), 1u);
  EXPECT_EQ(s.world.obstacles[0].pos, Eigen::Vector3d(2.0, 1.75, 0.2));
}

TEST(ScenarioLoader, GridMapRejectsBoundsBesideItAndCellsOffTheMap) {
  EXPECT_NE(placeOfError(gridMapScenario("{file: " + kEightByEight + "}",
                                         "  bounds: {min: [0, 0, 0], max: [4, 4, 2]}\n"))
                .find("world.bounds | comes from world.grid_map"),
            std::string::npos);
  EXPECT_NE(placeOfError(gridMapScenario("{file: " + kEightByEight + ", blocked: [[8, 0]]}"))
                .find("world.grid_map.blocked[0]"),
            std::string::npos);
  EXPECT_NE(placeOfError(gridMapScenario("{file: nowhere.map}")).find("file not found"),
            std::string::npos);
  // A start on a blocked cell is inside an obstacle.
  EXPECT_NE(placeOfError(gridMapScenario("{file: " + kEightByEight + ", blocked: [[0, 0]]}"))
                .find("inside world.obstacles["),
            std::string::npos);
}

// Vehicle names: 1 to 64 printable ASCII characters without spaces or '/'. A comma or a quote
// is legal (the CSV files quote them); a line break or a 200 KB name (repeated on every row of
// the log) is not.
TEST(ScenarioLoader, VehicleNamesHaveADocumentedCharacterSetAndLength) {
  const auto named = [](const std::string& quoted) {
    return replace(kGood, "name: uav1", "name: " + quoted);
  };
  EXPECT_EQ(parseScenario(named("'a,\"b\"'"), "s.yaml").vehicles[0].name, "a,\"b\"");
  EXPECT_EQ(parseScenario(named(std::string(64, 'n')), "s.yaml").vehicles[0].name.size(), 64u);
  EXPECT_NE(placeOfError(named(std::string(65, 'n')))
                .find("key vehicles[0].name | a vehicle name has at most 64 characters (this one "
                      "has 65)"),
            std::string::npos);
  EXPECT_NE(placeOfError(named("\"a\\nb\"")).find("(this one has a control character)"),
            std::string::npos);
  EXPECT_NE(placeOfError(named("\"a\\tb\"")).find("(this one has a control character)"),
            std::string::npos);
  EXPECT_NE(placeOfError(named("'a b'")).find("(this one has ' ')"), std::string::npos);
  EXPECT_NE(placeOfError(named("a/b")).find("(this one has '/')"), std::string::npos);
  EXPECT_NE(placeOfError(named("\"dr\\u00f6hne\"")).find("(this one has a non-ASCII character)"),
            std::string::npos);
}

TEST(ScenarioLoader, AGridMapOfScatteredCellsIsRefusedBeforeItsBoxesAreMade) {
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("cosim-checker-" + std::to_string(::getpid()) + ".map"))
                               .string();
  {
    std::ofstream out(file);
    out << "type octile\nheight 300\nwidth 300\nmap\n";
    for (int y = 0; y < 300; ++y) {
      for (int x = 0; x < 300; ++x) out << ((x + y) % 2 ? '@' : '.');
      out << '\n';
    }
  }
  // 45 000 blocked cells, none adjacent to another: 45 000 boxes, more than 10 000.
  EXPECT_NE(placeOfError(gridMapScenario("{file: " + file + ", cell: 0.1}"))
                .find("key world.grid_map.file | the map's blocked cells make more than 10000 "
                      "boxes"),
            std::string::npos);
  std::filesystem::remove(file);
}

TEST(ScenarioLoader, PointsTimesObstaclesBeyondTheCheckBudgetIsRefused) {
  std::string y = "world:\n  bounds: {min: [0, 0, 0], max: [100, 100, 10]}\n  obstacles:\n";
  for (int i = 0; i < 10000; ++i)
    y += "    - {type: sphere, pos: [" + std::to_string(1 + (i % 100) * 0.95) + ", " +
         std::to_string(1 + (i / 100) * 0.95) + ", 9], radius: 0.01}\n";
  y += "vehicles:\n  - {name: u, model: cf2, start: [1, 1, 1], waypoints: [";
  for (int i = 0; i < 20001; ++i) y += (i ? ", [" : "[") + std::to_string(1 + i % 90) + ", 2, 1]";
  y += "]}\n";
  // (2 + 20001) points x 10000 obstacles = 200030000 > 2e8.
  EXPECT_NE(placeOfError(y).find("key world | 20003 points x 10000 obstacles = 200030000 placement "
                                 "checks, more than 200000000"),
            std::string::npos);
}
