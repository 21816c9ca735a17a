// `cosim run` with ground robots: a team of ten URDF robots executes a conflict-free team plan
// in MuJoCo without touching each other; robots driven into each other do touch (the contact
// count can fail); a URDF with a missing mesh is bad input (exit 2 naming file and element).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "run/run_pipeline.h"
#include "tests/run/headless_run.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim {
namespace {

// Ten omni bases in two rows of five on a 0.7 m grid; each crosses to the other row's far end
// (crossing_straight: straight across), so the rows pass through each other (one step is 0.7 m
// at 0.48 m/s, 1.46 s).
std::string teamScenario(const std::string& planner, bool crossing_straight = false) {
  std::string s = "world:\n  bounds: {min: [0, 0, 0], max: [4.2, 4.2, 1]}\nvehicles:\n";
  // The grid has 6 x 6 cells of 0.7 m, centres at 0.35 + 0.7 k.
  const double bottom = 0.35, top = 3.85;
  for (int i = 0; i < 5; ++i) {
    const double cx = 0.35 + 0.7 * i;
    s += "  - {name: a" + std::to_string(i) + ", model: omni_base, start: [" + std::to_string(cx) +
         ", " + std::to_string(bottom) + ", 0], goal: [" +
         std::to_string(crossing_straight ? cx : 4.2 - cx) + ", " + std::to_string(top) + ", 0]}\n";
    s += "  - {name: b" + std::to_string(i) + ", model: omni_base, start: [" + std::to_string(cx) +
         ", " + std::to_string(top) + ", 0], goal: [" +
         std::to_string(crossing_straight ? cx : 4.2 - cx) + ", " + std::to_string(bottom) +
         ", 0]}\n";
  }
  s += "planner: {name: " + planner +
       ", resolution: 0.7, margin: 0.05}\n"
       "sim: {timestep: 0.002, control_rate: 50, max_time: 40}\n";
  return s;
}

RunRecord runText(const std::string& text, const std::string& name, std::string& metrics) {
  return test::runWithoutPictures(parseScenario(text, "ground_test.yaml"), name, metrics);
}

TEST(GroundTeamRun, TenRobotsOnValidCbsPlanHaveNoRobotContacts) {
  std::string metrics;
  const RunRecord r = runText(teamScenario("cbs"), "ground-team", metrics);
  EXPECT_EQ(r.exitStatus(), 0) << r.message;
  EXPECT_EQ(test::jsonNumber(metrics, "robots"), 10);
  EXPECT_EQ(test::jsonNumber(metrics, "robot_contacts"), 0);
  EXPECT_EQ(test::jsonNumber(metrics, "collisions"), 0);
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
  EXPECT_GT(test::jsonNumber(metrics, "min_robot_distance_m"), 0.0);
  // Every robot arrives within a second of its planned arrival (the smoothed reference
  // finishes 0.5 s after the plan; tracking adds little).
  EXPECT_LT(test::jsonNumber(metrics, "executed_makespan_s") -
                test::jsonNumber(metrics, "planned_makespan_s"),
            1.0);
  EXPECT_LT(test::jsonNumber(metrics, "max_error_m"), 0.1);
}

// The same team planned by LaCAM*, through the command line as a user runs it.
TEST(GroundTeamRun, CosimRunDrivesALacamPlanWithoutRobotContacts) {
  const auto dir = test::freshDir("ground-team-lacam");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "team.yaml") << teamScenario("lacam");
  const auto r = test::runCosim("run " + (dir / "team.yaml").string() + " --no-video --out " +
                                (dir / "run").string());
  EXPECT_EQ(r.status, 0) << r.err;
  const std::string metrics = test::slurp(dir / "run" / "metrics.json");
  EXPECT_NE(metrics.find("\"planner\": \"lacam\""), std::string::npos);
  EXPECT_EQ(test::jsonNumber(metrics, "robots"), 10);
  EXPECT_EQ(test::jsonNumber(metrics, "robot_contacts"), 0);
  EXPECT_EQ(test::jsonNumber(metrics, "collisions"), 0);
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
  EXPECT_EQ(test::jsonNumber(metrics, "planner_counters.conflicts"), 0);  // the validator's
  EXPECT_GT(test::jsonNumber(metrics, "planner_counters.first_solution_ms"), 0.0);
  std::filesystem::remove_all(dir);
}

TEST(GroundTeamRun, IndependentPathsThroughEachOtherMakeRobotContacts) {
  // Straight across, each robot's own shortest path: the rows meet head-on in the middle.
  std::string metrics;
  const RunRecord r = runText(teamScenario("independent_astar", true), "ground-clash", metrics);
  EXPECT_EQ(r.exitStatus(), 1);
  EXPECT_GE(test::jsonNumber(metrics, "robot_contacts"), 5);
}

TEST(GroundNavigationRun, RnaRobotCrossesBetweenPatrollingCylindersWithoutTouchingThem) {
  Scenario s = loadScenario(std::string(COSIM_SOURCE_DIR) +
                            "/experiments/scenarios/ground_moving_obstacles.yaml");
  RunRequest request;
  request.out_dir = test::freshDir("ground-nav");
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  const RunRecord r = executeRun(s, request);
  const std::string metrics = test::slurp(request.out_dir / "metrics.json");
  std::filesystem::remove_all(request.out_dir);
  EXPECT_EQ(r.exitStatus(), 0) << r.message;
  EXPECT_EQ(test::jsonNumber(metrics, "moving_obstacles"), 3);
  EXPECT_EQ(test::jsonNumber(metrics, "moving_obstacle_contacts"), 0);
  EXPECT_GT(test::jsonNumber(metrics, "min_moving_obstacle_distance_m"), 0.0);
  // The navigator re-planned around predicted collisions on the way.
  EXPECT_GT(test::jsonNumber(metrics, "planner_counters.replans"), 0);
}

TEST(GroundTeamRun, MissingMeshIsExitTwoNamingFileAndElement) {
  const auto dir = test::freshDir("ground-mesh");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "robot.urdf")
      << "<robot name=\"m\"><link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" "
         "ixy=\"0\" "
         "ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial><visual><geometry><mesh "
         "filename=\"shell.stl\"/></geometry></visual></link></robot>\n";
  std::ofstream(dir / "s.yaml") << "world:\n  bounds: {min: [0, 0, 0], max: [4, 4, 1]}\nvehicles:\n"
                                   "  - {model: robot.urdf, start: [1, 1, 0], goal: [3, 3, 0]}\n";
  const auto r = test::runCosim("run " + (dir / "s.yaml").string() + " --no-video --out " +
                                (dir / "out").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "robot.urdf").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("link 'base' <visual> 1 <mesh filename=\"shell.stl\">"), std::string::npos)
      << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim
