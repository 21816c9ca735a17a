#include <gtest/gtest.h>

#include "planning/input_error.h"
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
  EXPECT_EQ(s.planner_name, "astar");
  EXPECT_DOUBLE_EQ(s.planner_margin, 0.25);
  EXPECT_TRUE(s.planner_params.has("resolution"));
  EXPECT_FALSE(s.planner_params.has("margin"));
  EXPECT_EQ(s.sim.seed, 7u);
}

TEST(ScenarioLoader, SetOverridesApplyBeforeValidation) {
  const Scenario s = parseScenario(kGood, "s.yaml", {"planner.name=theta_star", "sim.seed=3"});
  EXPECT_EQ(s.planner_name, "theta_star");
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
  EXPECT_NE(e.find("inside obstacle 3"), std::string::npos) << e;
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
