// `cosim run` with ground robots and quadrotors in one world: the robots execute their team plan
// while the quadrotors fly their own plans overhead, in the same simulation loop; contacts
// between a quadrotor and a robot are collisions; the quadrotors' faults (saturation) end the run
// as in a flight; the `aerial` section is strict.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/input_error.h"
#include "run/run_pipeline.h"
#include "tests/run/headless_run.h"
#include "tests/support/json_fields.h"

namespace cosim {
namespace {

// Four omni bases swap the two rows of a 4.2 m square floor (0.7 m grid, CBS) while two
// quadrotors cross it diagonally 1.2 and 1.8 m above them, each with its own Theta* path and a
// minimum-snap trajectory.
const std::string kTeamWithUavs =
    "world:\n"
    "  bounds: {min: [0, 0, 0], max: [4.2, 4.2, 2.5]}\n"
    "vehicles:\n"
    "  - {name: a0, model: omni_base, start: [0.35, 0.35, 0], goal: [3.85, 3.85, 0]}\n"
    "  - {name: a1, model: omni_base, start: [1.75, 0.35, 0], goal: [2.45, 3.85, 0]}\n"
    "  - {name: b0, model: omni_base, start: [0.35, 3.85, 0], goal: [3.85, 0.35, 0]}\n"
    "  - {name: b1, model: omni_base, start: [1.75, 3.85, 0], goal: [2.45, 0.35, 0]}\n"
    "  - {name: uav1, model: quad_1500g, start: [0.6, 1.4, 1.2], goal: [3.6, 2.8, 1.2]}\n"
    "  - {name: uav2, model: cf2, start: [3.6, 1.4, 1.8], goal: [0.6, 2.8, 1.8]}\n"
    "planner: {name: cbs, resolution: 0.7, margin: 0.05}\n"
    "aerial:\n"
    "  planner: {name: theta_star, resolution: 0.2, margin: 0.2}\n"
    "  trajectory: {mode: minimum_snap, max_speed: 1.0}\n"
    "  controller: {name: geometric}\n"
    "sim: {timestep: 0.002, control_rate: 250, max_time: 40}\n";

// A robot creeps 0.4 m across a quadrotor's straight path, which runs `height` above the floor
// (the omni base's chassis spans 0.02 to 0.10 m).
std::string crossing(double height, const std::string& model = "cf2") {
  const std::string z = std::to_string(height);
  return "world:\n  bounds: {min: [0, 0, 0], max: [4, 3, 2]}\nvehicles:\n"
         "  - {name: r0, model: omni_base, start: [2.0, 1.3, 0], goal: [2.0, 1.7, 0]}\n"
         "  - {name: uav1, model: " +
         model + ", start: [0.5, 1.5, " + z + "], goal: [3.5, 1.5, " + z +
         "]}\n"
         "aerial:\n  trajectory: {mode: minimum_snap, max_speed: 1.0}\n"
         "sim: {timestep: 0.002, control_rate: 250, max_time: 10}\n";
}

RunRecord runText(const std::string& text, const std::string& name, std::string& metrics,
                  const std::vector<std::string>& overrides = {}) {
  return test::runWithoutPictures(parseScenario(text, "mixed_test.yaml", overrides), name, metrics);
}

// The metrics.json entry of one vehicle (its object in the "vehicles" list, which holds no
// nested object), braces included.
std::string vehicleEntry(const std::string& metrics, const std::string& name) {
  const auto at = metrics.find("\"name\": \"" + name + "\"");
  if (at == std::string::npos) return "";
  const auto from = metrics.rfind('{', at);
  return metrics.substr(from, metrics.find('}', at) + 1 - from);
}

TEST(GroundTeamWithUavs, RobotsOnCbsPlanAndQuadrotorsOverheadAllArriveWithoutContacts) {
  std::string metrics;
  const RunRecord r = runText(kTeamWithUavs, "mixed-team", metrics);
  EXPECT_EQ(r.exitStatus(), 0) << r.message;
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
  EXPECT_EQ(test::jsonNumber(metrics, "robots"), 4);
  EXPECT_EQ(test::jsonNumber(metrics, "uavs"), 2);
  EXPECT_EQ(test::jsonNumber(metrics, "collisions"), 0);
  EXPECT_EQ(test::jsonNumber(metrics, "robot_contacts"), 0);
  EXPECT_EQ(test::jsonNumber(metrics, "robot_uav_contacts"), 0);
  // The robots still follow their timed plan closely and arrive on time.
  EXPECT_LT(test::jsonNumber(metrics, "max_error_m"), 0.1);
  EXPECT_LT(test::jsonNumber(metrics, "executed_makespan_s") -
                test::jsonNumber(metrics, "planned_makespan_s"),
            1.0);
  for (const std::string uav : {"uav1", "uav2"}) {
    const std::string e = vehicleEntry(metrics, uav);
    ASSERT_FALSE(e.empty()) << metrics;
    EXPECT_TRUE(test::jsonTrue(e, "reached_goal")) << e;
    EXPECT_NE(e.find("\"kind\": \"quadrotor\""), std::string::npos) << e;
    // It flew its diagonal (3.3 m from start to goal) along its trajectory.
    EXPECT_GT(test::jsonNumber(e, "flown_length_m"), 3.2) << e;
    EXPECT_LT(test::jsonNumber(e, "rmse_m"), 0.05) << e;
    EXPECT_EQ(test::jsonNumber(e, "collisions"), 0) << e;
  }
}

TEST(GroundTeamWithUavs, QuadrotorCrossingARobotAtItsHeightIsARobotUavContact) {
  std::string low, high;
  const RunRecord through = runText(crossing(0.06), "mixed-cross-low", low);
  EXPECT_EQ(through.exitStatus(), 1);
  EXPECT_EQ(through.message, "collision");
  EXPECT_GE(test::jsonNumber(low, "robot_uav_contacts"), 1) << low;
  EXPECT_GE(test::jsonNumber(low, "collisions"), 1);
  EXPECT_GE(test::jsonNumber(vehicleEntry(low, "r0"), "contacts"), 1) << low;
  // The same crossing 0.5 m up passes over the robot.
  const RunRecord over = runText(crossing(0.5), "mixed-cross-high", high);
  EXPECT_EQ(over.exitStatus(), 0) << over.message;
  EXPECT_EQ(test::jsonNumber(high, "robot_uav_contacts"), 0);
  EXPECT_EQ(test::jsonNumber(high, "collisions"), 0);
}

TEST(GroundTeamWithUavs, SaturatedQuadrotorEndsTheRunAsAFault) {
  // Absurd position gains on the 1.5 kg quadrotor (as in the flight test of the same fault).
  std::string metrics;
  const RunRecord r =
      runText(crossing(0.8, "quad_1500g"), "mixed-saturated", metrics,
              {"aerial.controller.name=geometric", "aerial.controller.gains.k_x_xy=10000"});
  EXPECT_EQ(r.exitStatus(), 1);
  EXPECT_NE(r.message.find("saturated"), std::string::npos) << r.message;
  EXPECT_NE(metrics.find("\"fault\": \"saturated\""), std::string::npos) << metrics;
  // From the log (sampled at the robots' 50 Hz): the 2 s limit, give or take a sample. The
  // sample times are sums of 0.02 s steps: 99 of them give 1.9799999999998394, which
  // metrics.json now writes in full (it wrote 1.98 with 10 digits).
  EXPECT_GE(test::jsonNumber(metrics, "longest_saturation_s"), 1.98 - 1e-9);
}

TEST(GroundTeamWithUavs, BundledScenarioFliesOverTheTeamWithoutContacts) {
  std::string metrics;
  const RunRecord r =
      test::runWithoutPictures(loadScenario(std::string(COSIM_SOURCE_DIR) +
                                            "/experiments/scenarios/ground_team_with_uavs.yaml"),
                               "mixed-bundled", metrics);
  EXPECT_EQ(r.exitStatus(), 0) << r.message;
  EXPECT_EQ(test::jsonNumber(metrics, "robots"), 8);
  EXPECT_EQ(test::jsonNumber(metrics, "uavs"), 2);
  EXPECT_EQ(test::jsonNumber(metrics, "collisions"), 0);
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
}

TEST(GroundTeamWithUavs, AerialSectionIsStrict) {
  // Only for quadrotors beside ground robots.
  const std::string flight_only =
      "world: {bounds: {min: [0, 0, 0], max: [4, 3, 2]}}\n"
      "vehicles: [{name: u, model: cf2, start: [1, 1, 1], goal: [3, 2, 1]}]\n"
      "aerial: {planner: {name: astar}}\n";
  try {
    parseScenario(flight_only, "mixed_test.yaml");
    ADD_FAILURE() << "accepted an aerial section without ground robots";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key aerial"), std::string::npos) << e.what();
  }
  // Its sections are the top-level ones' (a misspelt key is named with its path).
  try {
    parseScenario(crossing(0.5), "mixed_test.yaml", {"aerial.trajectory.mode=spline"});
    ADD_FAILURE() << "accepted an unknown trajectory mode";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("aerial.trajectory.mode"), std::string::npos) << e.what();
  }
  // Over ground robots each quadrotor plans alone (a team planner plans quadrotor-only
  // scenarios: tests/run/quadrotor_team_run_test.cpp), and says so.
  std::string metrics;
  try {
    runText(crossing(0.5), "mixed-bad-planner", metrics, {"aerial.planner.name=cbs"});
    ADD_FAILURE() << "accepted a team planner for quadrotors over ground robots";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("single-agent planner 'cbs'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cosim

namespace cosim {
namespace {

// Wind and rotor drag push the quadrotors (their tracking error grows) and leave the robots
// alone (their execution is the same to the last digit); a ground-only scenario with wind is bad
// input rather than a silently calm run.
TEST(GroundTeamWithUavs, WindActsOnTheQuadrotorsOnly) {
  std::string calm, windy;
  ASSERT_EQ(runText(kTeamWithUavs, "mixed-calm", calm).exitStatus(), 0);
  const RunRecord r =
      runText(kTeamWithUavs, "mixed-windy", windy,
              {"disturbances.wind=[1.5, 0, 0]", "disturbances.gust=0.3", "disturbances.drag=0.05"});
  EXPECT_EQ(r.exitStatus(), 0) << r.message;
  EXPECT_GT(test::jsonNumber(windy, "uav_rmse_m"), 3.0 * test::jsonNumber(calm, "uav_rmse_m"));
  EXPECT_EQ(test::jsonNumber(windy, "rmse_m"), test::jsonNumber(calm, "rmse_m"));
  EXPECT_EQ(test::jsonNumber(windy, "executed_makespan_s"),
            test::jsonNumber(calm, "executed_makespan_s"));

  const std::string robots_only =
      "world:\n  bounds: {min: [0, 0, 0], max: [4.2, 4.2, 2.5]}\nvehicles:\n"
      "  - {name: a0, model: omni_base, start: [0.35, 0.35, 0], goal: [3.85, 3.85, 0]}\n"
      "disturbances: {wind: [3, 0, 0], drag: 0.1}\n";
  std::string metrics;
  try {
    runText(robots_only, "ground-windy", metrics);
    ADD_FAILURE() << "wind on a robots-only scenario was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "disturbances");
  }
}

}  // namespace
}  // namespace cosim
