// End to end: bad inputs of every kind (malformed, truncated, wrong types, huge numbers, NaN,
// unreachable, overlapping, empty) make the built program exit 2 (bad input) or 1 (task failed)
// with one stderr line naming the problem, and never leave a result file that looks finished.
// The README's "Bad inputs and faults" table lists these cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/experiments/cli_test_support.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// A small valid scenario, and pieces to break.
const std::string kWorld =
    "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
    "        obstacles: [{type: box, pos: [10, 10, 3], size: [2, 8, 6]}]}\n";
const std::string kVehicle =
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n";
const std::string kPlanner = "planner: {name: astar, resolution: 0.5}\n";
const std::string kValid = kWorld + kVehicle + kPlanner;

std::string withWorld(const std::string& world) {
  return world + kVehicle + kPlanner;
}
std::string withVehicles(const std::string& vehicles) {
  return kWorld + vehicles + kPlanner;
}
std::string withPlanner(const std::string& planner) {
  return kWorld + kVehicle + planner;
}

std::string mapText(int w, int h, const std::string& rows) {
  return "type octile\nheight " + std::to_string(h) + "\nwidth " + std::to_string(w) + "\nmap\n" +
         rows;
}

struct BadInput {
  std::string name;
  // {in} is replaced by the file holding `content`, {in2} by the one holding `content2`, {out}
  // by a fresh output path, {data} by tests/data/movingai.
  std::string args;
  std::string content, content2;
  int exit_code;
  std::string message;  // the stderr line must contain this ({in} as in args)
};

void PrintTo(const BadInput& c, std::ostream* os) {
  *os << c.name;
}

std::vector<BadInput> badInputs() {
  const std::string plan = "plan {in} --out {out}";
  const std::string bench = "grid-bench {in} {in2} --planner astar --out {out}/bench.csv";
  const std::string scen8 = "version 1\n0\tx.map\t8\t8\t0\t0\t7\t7\t9.89949494\n";
  std::string rows8;
  for (int i = 0; i < 8; ++i) rows8 += "........\n";
  const std::string map8 = mapText(8, 8, rows8);
  return {
      // Scenario files: malformed, truncated, empty.
      {"empty_scenario", plan, "", "", 2, "missing 'world' section"},
      {"unclosed_flow_map", plan, "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}\n", "", 2,
       "malformed YAML"},
      {"truncated_scenario", plan, kValid.substr(0, 60), "", 2, "malformed YAML"},
      {"top_level_list", plan, "- world\n- vehicles\n", "", 2, "must be a mapping"},
      {"binary_garbage", plan, std::string("\x01\x02\xff\xfe\x00\x7f", 6), "", 2, "malformed YAML"},
      {"deeply_nested", plan, "world: " + std::string(20000, '[') + std::string(20000, ']') + "\n",
       "", 2, "malformed YAML"},
      {"unknown_top_level_key", plan, kValid + "wrld: 1\n", "", 2, "unknown key 'wrld'"},
      // World: wrong types, huge numbers, NaN.
      {"bounds_inverted", plan, withWorld("world: {bounds: {min: [0, 0, 0], max: [20, -20, 6]}}\n"),
       "", 2, "max must exceed min"},
      {"bounds_nan", plan, withWorld("world: {bounds: {min: [0, 0, 0], max: [.nan, 20, 6]}}\n"), "",
       2, "world.bounds.max[0]: must be a number"},
      {"bounds_huge", plan, withWorld("world: {bounds: {min: [0, 0, 0], max: [1e7, 20, 6]}}\n"), "",
       2, "larger than 10 km"},
      {"obstacles_not_list", plan,
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, obstacles: 3}\n"), "", 2,
       "world.obstacles: must be a list"},
      {"obstacle_unknown_type", plan,
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
                 "        obstacles: [{type: pyramid, pos: [5, 5, 1]}]}\n"),
       "", 2, "unknown obstacle type 'pyramid'"},
      {"obstacle_negative_size", plan,
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
                 "        obstacles: [{type: box, pos: [5, 5, 1], size: [1, -2, 1]}]}\n"),
       "", 2, "sizes must be positive"},
      {"cylinder_missing_height", plan,
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
                 "        obstacles: [{type: cylinder, pos: [5, 5, 1], radius: 1}]}\n"),
       "", 2, "needs 'radius' and 'height'"},
      {"obstacle_radius_infinite", plan,
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
                 "        obstacles: [{type: sphere, pos: [5, 5, 1], radius: 1e999}]}\n"),
       "", 2, "radius"},
      // Vehicles: overlapping, outside, wrong types, missing.
      {"start_inside_obstacle", plan,
       withVehicles(
           "vehicles: [{name: uav1, model: cf2, start: [10, 10, 1], goal: [18, 18, 1]}]\n"),
       "", 2, "inside obstacle 1"},
      {"goal_outside_world", plan,
       withVehicles("vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [25, 18, 1]}]\n"),
       "", 2, "outside the world bounds"},
      {"start_wrong_type", plan,
       withVehicles("vehicles: [{name: uav1, model: cf2, start: here, goal: [18, 18, 1]}]\n"), "",
       2, "vehicles[0].start: must be a list of 3 numbers"},
      {"start_two_numbers", plan,
       withVehicles("vehicles: [{name: uav1, model: cf2, start: [2, 2], goal: [18, 18, 1]}]\n"), "",
       2, "vehicles[0].start: must be a list of 3 numbers"},
      {"start_overflowing_number", plan,
       withVehicles(
           "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1e999], goal: [18, 18, 1]}]\n"),
       "", 2, "must be a finite number"},
      {"no_vehicles", plan, kWorld + kPlanner, "", 2, "missing 'vehicles' list"},
      {"empty_vehicle_list", plan, withVehicles("vehicles: []\n"), "", 2,
       "must be a non-empty list"},
      {"duplicate_vehicle_names", plan,
       withVehicles("vehicles: [{name: a, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]},\n"
                    "           {name: a, model: cf2, start: [2, 4, 1], goal: [18, 16, 1]}]\n"),
       "", 2, "duplicate vehicle name 'a'"},
      {"unknown_model", plan,
       withVehicles(
           "vehicles: [{name: uav1, model: blimp, start: [2, 2, 1], goal: [18, 18, 1]}]\n"),
       "", 2, "no model 'blimp'"},
      {"missing_urdf", plan,
       withVehicles(
           "vehicles: [{name: r, model: robots/none.urdf, start: [2, 2, 0], goal: [18, 18, 0]}]\n"),
       "", 2, "no model 'robots/none.urdf'"},
      {"vehicle_without_goal", plan,
       withVehicles("vehicles: [{name: uav1, model: cf2, start: [2, 2, 1]}]\n"), "", 2,
       "needs a 'goal' or 'waypoints'"},
      // Planner, trajectory, controller, simulation settings.
      {"unknown_planner", plan, withPlanner("planner: {name: teleport}\n"), "", 2,
       "unknown planner 'teleport'"},
      {"misspelt_planner_parameter", plan, withPlanner("planner: {name: astar, resolutoin: 0.5}\n"),
       "", 2, "unknown parameter 'resolutoin'"},
      // Quadrotors over ground robots: the `aerial` section.
      {"aerial_without_ground_robots", plan, kValid + "aerial: {planner: {name: astar}}\n", "", 2,
       "key aerial: is for the quadrotors of a scenario with ground robots too"},
      {"aerial_team_planner", "run {in} --no-video --out {out}",
       withVehicles("vehicles: [{name: r, model: omni_base, start: [2, 2, 0], goal: [18, 2, 0]},\n"
                    "           {name: u, model: cf2, start: [2, 18, 1], goal: [18, 18, 1]}]\n"
                    "aerial: {planner: {name: cbs}}\n"),
       "", 2, "aerial.planner.name: unknown single-agent planner 'cbs'"},
      {"moving_obstacles_with_quadrotors_only", "run {in} --no-video --out {out}",
       "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
       "        moving_obstacles: [{type: cylinder, radius: 0.5, height: 1, path: [[10, 5]]}]}\n" +
           kVehicle + kPlanner,
       "", 2, "moving obstacles need ground robots"},
      {"parameter_wrong_type", plan, withPlanner("planner: {name: astar, resolution: fast}\n"), "",
       2, "'resolution' must be a number"},
      {"parameter_out_of_range", plan, withPlanner("planner: {name: astar, resolution: 0}\n"), "",
       2, "'resolution' = 0 is outside"},
      {"grid_too_large", plan,
       "world: {bounds: {min: [0, 0, 0], max: [9000, 9000, 9000]}}\n" + kVehicle +
           "planner: {name: astar, resolution: 0.01}\n",
       "", 2, "exceeds the limit"},
      // The grid is a planner's, deep in the run, but the message names the scenario file.
      {"grid_too_large_names_the_scenario", "run {in} --no-video --quiet --out {out}",
       "world: {bounds: {min: [0, 0, 0], max: [9000, 9000, 9000]}}\n" + kVehicle +
           "planner: {name: astar, resolution: 0.01}\n",
       "", 2, "{in}: grid: 900000x900000x900000 = "},
      {"unknown_trajectory_mode", plan, kValid + "trajectory: {mode: teleport}\n", "", 2,
       "must be 'waypoints' or 'minimum_snap'"},
      {"unknown_controller", plan, kValid + "controller: {name: pid}\n", "", 2,
       "must be 'cascade', 'geometric', 'indi' or 'dsl_pid'"},
      {"drag_compensation_on_cascade", plan,
       kValid + "controller: {name: cascade, drag_compensation: true}\n", "", 2,
       "controller.drag_compensation: applies to the 'geometric' and 'indi' controllers"},
      // Sensing, estimation, aerodynamics (the realism issue).
      {"unknown_sensor_preset", plan, kValid + "sensors: {preset: lidar}\n", "", 2,
       "key sensors.preset: unknown preset 'lidar' (ideal, mocap, onboard)"},
      {"negative_sensor_noise", plan, kValid + "sensors: {preset: mocap, position: {noise: -0.1}}\n",
       "", 2, "key sensors.position.noise: must be >= 0"},
      {"latency_longer_than_run", plan,
       kValid + "sensors: {preset: mocap, attitude: {latency: 0.5}}\nsim: {max_time: 0.3}\n", "",
       2, "key sensors.attitude.latency: latency 0.5 s is longer than the run"},
      {"ekf_without_sensors", plan, kValid + "estimator: {name: ekf}\n", "", 2,
       "key estimator.name: 'ekf' needs sensors to fuse"},
      {"ekf_without_position_sensor", plan,
       kValid + "sensors: {imu: {rate: 500}}\nestimator: {name: ekf}\n", "", 2,
       "key estimator.name: 'ekf' needs a position sensor"},
      {"sensor_faster_than_physics", plan,
       kValid + "sensors: {preset: mocap, imu: {rate: 5000}}\n", "", 2,
       "key sensors.imu.rate: rate 5000 Hz is above the physics rate"},
      {"wind_without_drag", plan, kValid + "disturbances: {wind: [3, 0, 0]}\n", "", 2,
       "key disturbances.wind: wind acts through drag and this scenario has none"},
      {"model_error_absurd", plan, kValid + "model_error: {mass: 3}\n", "", 2,
       "key model_error.mass"},
      {"timestep_huge", plan, kValid + "sim: {timestep: 1.0}\n", "", 2, "sim.timestep"},
      {"rates_incompatible", plan, kValid + "sim: {timestep: 0.0007, control_rate: 500}\n", "", 2,
       "whole multiple of the control rate"},
      {"max_time_negative", plan, kValid + "sim: {max_time: -5}\n", "", 2, "sim.max_time"},
      {"seed_negative", plan, kValid + "sim: {seed: -1}\n", "", 2, "sim.seed"},
      {"log_too_long", "run {in} --no-video --out {out}",
       kValid + "sim: {max_time: 86400, control_rate: 10000, timestep: 0.0001}\n", "", 2,
       "more than 20 million"},
      {"odd_video_width", "run {in} --no-video --out {out}",
       kValid + "render: {width: 641, height: 480}\n", "", 2, "must be even"},
      // Unreachable: a wall across the whole world. Exit 1 (the task failed), not a crash.
      {"unreachable_goal", "run {in} --no-video --out {out}",
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
                 "        obstacles: [{type: box, pos: [10, 10, 3], size: [2, 30, 16]}]}\n"),
       "", 1, "no path"},
      // Overlapping: the centre is clear but the vehicle's body (plus margin) touches the wall.
      {"start_touching_obstacle", plan,
       withVehicles(
           "vehicles: [{name: uav1, model: cf2, start: [8.95, 10, 1], goal: [18, 18, 1]}]\n"),
       "", 1, "start cell is blocked"},
      // A fault in flight: absurd position gains keep the rotors saturated; the run stops.
      {"absurd_gains_saturate", "run {in} --no-video --out {out}",
       kWorld +
           "vehicles: [{name: uav1, model: quad_1500g, start: [2, 2, 1], goal: [18, 18, 1]}]\n" +
           kPlanner +
           "controller: {name: geometric, gains: {k_x_xy: 10000}}\nsim: {max_time: 30}\n",
       "", 1, "rotors stayed saturated for over 2 s"},
      // Command line and files.
      {"scenario_missing", "plan {out}/none.yaml --out {out}", "", "", 2,
       "cannot open scenario file"},
      {"set_without_value", "plan {in} --set planner --out {out}", kValid, "", 2,
       "expected key=value"},
      {"out_under_regular_file", "plan {in} --out /etc/passwd/x", kValid, "", 2,
       "cannot create folder"},
      // --set values are placed at the assignment, not at "line 1" of the file.
      {"set_parameter_wrong_type", "plan {in} --set planner.resolution=fast --out {out}", kValid,
       "", 2,
       "{in}: --set planner.resolution=fast, key planner.resolution: 'resolution' must be a "
       "number, got 'fast'"},
      {"set_value_wrong_type", "plan {in} --set sim.timestep=abc --out {out}", kValid, "", 2,
       "{in}: --set sim.timestep=abc, key sim.timestep: must be a number, got 'abc'"},
      {"set_unknown_key", "plan {in} --set wrld.x=1 --out {out}", kValid, "", 2,
       "{in}: --set wrld.x=1, key wrld: unknown key 'wrld'"},
      // NUL and other control bytes quoted from the input are escaped, not echoed raw (a NUL
      // cut the message short).
      {"planner_name_with_nul", plan, withPlanner("planner: {name: \"te\\0st\\x1b\"}\n"), "", 2,
       "unknown planner 'te\\x00st\\x1b' (known: "},
      // MovingAI maps and scenarios.
      {"map_short_row", bench, mapText(3, 2, "...\n..\n"), scen8, 2, "expected 3"},
      {"map_huge_dimensions", bench, mapText(99999999, 99999999, ""), scen8, 2,
       "height must be between"},
      {"map_nul_character", bench, mapText(3, 2, std::string("..\0\n...\n", 8)), scen8, 2,
       "line 5, column 3: unknown map character '\\x00'"},
      {"map_truncated", bench, mapText(8, 8, "........\n........\n"), scen8, 2,
       "expected 8 map rows, found 2"},
      {"scen_outside_map", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\t99\t3\t5.0\n", 2,
       "outside the stated map size"},
      {"scen_nan_length", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\t7\t7\tnan\n", 2,
       "optimal_length 'nan' is not a number"},
      {"scen_truncated_line", bench, map8, "version 1\n0\tx.map\t8\t8\t0\t0\n", 2,
       "expected 9 fields"},
      {"mapf_too_many_agents", "mapf {in} {in2} --agents 100 --planner cbs --out {out}", map8,
       scen8, 2, "fewer than the 100 agents"},
      {"mapf_range_backwards", "mapf {in} {in2} --agents 10:5:1 --planner lacam --out {out}", map8,
       scen8, 2, "--agents 10:5:1: STOP is below START"},
      {"mapf_range_not_numbers", "mapf {in} {in2} --agents 1:x:2 --planner lacam --out {out}", map8,
       scen8, 2, "expected N or START:STOP:STEP"},
      {"mapf_benchmark_unknown_planner",
       "mapf {in} {in2} --agents 1:3:1 --planner lacam,teleport --out {out}", map8, scen8, 2,
       "unknown multi-robot planner 'teleport'"},
  };
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ExitsWithOneLineNamingTheProblemAndLeavesNoResult) {
  const BadInput& c = GetParam();
  const fs::path dir = freshDir("bad-input-" + c.name);
  fs::create_directories(dir);
  const bool is_map = c.args.rfind("grid-bench", 0) == 0 || c.args.rfind("mapf", 0) == 0;
  const fs::path in = dir / (is_map ? "x.map" : "scenario.yaml");
  const fs::path in2 = dir / "x.scen";
  std::ofstream(in, std::ios::binary) << c.content;
  std::ofstream(in2, std::ios::binary) << c.content2;
  const fs::path out = dir / "out";
  std::string args = replaceAll(c.args, "{in}", in.string());
  args = replaceAll(args, "{in2}", in2.string());
  args = replaceAll(args, "{out}", out.string());

  const CommandResult r = runCosim(args);
  EXPECT_EQ(r.status, c.exit_code) << args << "\nstderr: " << r.err << "\nstdout: " << r.out;
  // The program's own message, never a crash report or an internal error.
  const std::string all = r.err + r.out;
  const std::string message = replaceAll(c.message, "{in}", in.string());
  EXPECT_NE(all.find(message), std::string::npos) << "stderr: " << r.err << "\nstdout: " << r.out;
  // No raw control bytes from the input (a NUL would cut the line, an escape drive the terminal).
  EXPECT_EQ(std::count_if(r.err.begin(), r.err.end(),
                          [](unsigned char ch) { return (ch < 0x20 && ch != '\n') || ch == 0x7f; }),
            0)
      << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Sanitizer"), std::string::npos) << r.err;
  if (c.exit_code == 2) {
    // Bad input: one line on stderr, and nothing written.
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const char* f : {"metrics.json", "plan.json", "bench.csv", "mapf.json", "path.csv"})
      EXPECT_FALSE(fs::exists(out / f)) << f;
  } else if (fs::exists(out / "metrics.json")) {
    // A failed task may write its result, but it must say it failed.
    const std::string metrics = slurp(out / "metrics.json");
    EXPECT_FALSE(jsonTrue(metrics, "reached_goal")) << metrics;
    EXPECT_EQ(jsonNumber(metrics, "status"), 1.0) << metrics;
    if (c.name == "absurd_gains_saturate") {
      EXPECT_NE(metrics.find("\"fault\": \"saturated\""), std::string::npos) << metrics;
      EXPECT_GT(jsonNumber(metrics, "longest_saturation_s"), 2.0) << metrics;
    }
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInputTest, ::testing::ValuesIn(badInputs()),
                         [](const ::testing::TestParamInfo<BadInput>& i) { return i.param.name; });

TEST(BadInputTable, CoversAtLeastThirtyDistinctBadInputs) {
  const auto cases = badInputs();
  EXPECT_GE(cases.size(), 30u);
  std::vector<std::string> names;
  for (const auto& c : cases) names.push_back(c.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

}  // namespace
}  // namespace cosim::test
