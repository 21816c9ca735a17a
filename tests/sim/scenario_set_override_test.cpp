// --set on list elements: `vehicles[0].goal=[...]`, nested indices, and clear errors for indices
// that do not exist (the file's lists are never grown by an override).
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "sim/scenario.h"

using namespace cosim;

namespace {

const char* kTwoVehicles = R"(world:
  bounds: {min: [0, 0, 0], max: [20, 20, 8]}
  obstacles:
    - {type: box, pos: [10, 10, 2.5], size: [4, 2, 5]}
    - {type: cylinder, pos: [5, 15, 3], radius: 1.0, height: 6}
vehicles:
  - {name: uav1, model: quad_1500g, start: [2, 2, 2], goal: [18, 18, 4]}
  - {name: uav2, model: quad_1500g, start: [2, 4, 2], goal: [18, 16, 4]}
planner: {name: astar, resolution: 0.5}
)";

std::string errorOf(const std::vector<std::string>& sets) {
  try {
    parseScenario(kTwoVehicles, "s.yaml", sets);
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

}  // namespace

TEST(ScenarioSetOverride, ReachesListElementsAndTheirKeys) {
  const Scenario s =
      parseScenario(kTwoVehicles, "s.yaml",
                    {"vehicles[0].goal=[36,20,2.5]", "vehicles[1].model=cf2",
                     "world.obstacles[1].radius=0.5", "world.bounds.max=[40, 30, 8]"});
  EXPECT_EQ(s.vehicles[0].goal(), Eigen::Vector3d(36, 20, 2.5));
  EXPECT_EQ(s.vehicles[1].model, "cf2");
  EXPECT_EQ(s.vehicles[0].model, "quad_1500g");  // the other element is untouched
  EXPECT_EQ(s.vehicles[1].goal(), Eigen::Vector3d(18, 16, 4));
  EXPECT_DOUBLE_EQ(s.world.obstacles[1].radius, 0.5);
  EXPECT_DOUBLE_EQ(s.world.obstacles[0].size.x(), 4.0);
}

TEST(ScenarioSetOverride, NestedIndicesReplaceOneElementOfAnInnerList) {
  const Scenario s =
      parseScenario(kTwoVehicles, "s.yaml",
                    {"vehicles[1].waypoints=[[5, 5, 2], [8, 4, 2]]",
                     "vehicles[1].waypoints[1]=[9, 3, 2]", "vehicles[1].waypoints[0][2]=3"});
  ASSERT_EQ(s.vehicles[1].waypoints.size(), 3u);  // two waypoints, then the goal
  EXPECT_EQ(s.vehicles[1].waypoints[0], Eigen::Vector3d(5, 5, 3));
  EXPECT_EQ(s.vehicles[1].waypoints[1], Eigen::Vector3d(9, 3, 2));
}

TEST(ScenarioSetOverride, AWholeElementCanBeReplaced) {
  const Scenario s =
      parseScenario(kTwoVehicles, "s.yaml",
                    {"vehicles[1]={name: scout, model: cf2, start: [3, 3, 1], goal: [17, 3, 1]}"});
  EXPECT_EQ(s.vehicles[1].name, "scout");
  EXPECT_EQ(s.vehicles[1].goal(), Eigen::Vector3d(17, 3, 1));
}

TEST(ScenarioSetOverride, IndicesThatDoNotExistAreClearErrors) {
  EXPECT_EQ(errorOf({"vehicles[2].goal=[1,1,1]"}),
            "command line: --set vehicles[2].goal=[1,1,1]: index 2 is out of range: vehicles has "
            "2 elements (indices 0 to 1)");
  EXPECT_EQ(errorOf({"planner[0].name=rrt"}),
            "command line: --set planner[0].name=rrt: planner is not a list, so it has no element "
            "planner[0]");
  EXPECT_EQ(errorOf({"aerial[0].planner=x"}),
            "command line: --set aerial[0].planner=x: aerial is not in the scenario, so it has no "
            "element [0] to set");
  EXPECT_EQ(errorOf({"vehicles[-1].goal=[1,1,1]"}),
            "command line: --set vehicles[-1].goal=[1,1,1]: 'vehicles[-1]': a list element is "
            "written name[N], N a whole number from 0");
  EXPECT_EQ(errorOf({"vehicles[0]x.goal=[1,1,1]"}),
            "command line: --set vehicles[0]x.goal=[1,1,1]: 'vehicles[0]x': a list element is "
            "written name[N], N a whole number from 0");
  // Read as index 0, a later error about the value could not be placed at this assignment.
  EXPECT_EQ(errorOf({"vehicles[00].goal=[1,1,1]"}),
            "command line: --set vehicles[00].goal=[1,1,1]: 'vehicles[00]': write the index "
            "without leading zeros (vehicles[0])");
  EXPECT_EQ(errorOf({"[0].goal=[1,1,1]"}),
            "command line: --set [0].goal=[1,1,1]: empty key in path '[0].goal'");
}

TEST(ScenarioSetOverride, ABadValueInAnElementIsPlacedAtTheAssignment) {
  EXPECT_EQ(errorOf({"vehicles[1].goal=[1,2]"}),
            "s.yaml: --set vehicles[1].goal=[1,2], key vehicles[1].goal: must be a list of 3 "
            "numbers [x, y, z]");
  EXPECT_EQ(errorOf({"vehicles[0].goal=[10,10,2]"}),
            "s.yaml: --set vehicles[0].goal=[10,10,2], key vehicles[0].goal: point is inside "
            "world.obstacles[0] (obstacles are numbered from 0 in the file's order, as --set "
            "numbers them)");
}
