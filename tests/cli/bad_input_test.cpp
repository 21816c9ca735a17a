// End to end: bad inputs of every kind (malformed, truncated, wrong types, huge numbers, NaN,
// unreachable, overlapping, empty) make the built program exit 2 (bad input) or 1 (task failed)
// with one stderr line naming the problem, and never leave a result file that looks finished.
// The README's "Bad inputs and faults" table lists these cases.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

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
  // by a fresh output path, {dir} by the case's folder (the program runs there).
  std::string args;
  std::string content, content2;
  int exit_code;
  std::string message;  // the stderr line must contain this ({in}, {dir} as in args)
  // More files in the case's folder (name relative to it, content), and a FIFO to make there.
  std::vector<std::pair<std::string, std::string>> files = {};
  std::string fifo = "";
};

void PrintTo(const BadInput& c, std::ostream* os) {
  *os << c.name;
}

// A MovingAI map of w x h cells, every cell free, or a checkerboard (every other cell blocked).
std::string wideMap(int w, int h, bool checkerboard) {
  std::string rows;
  rows.reserve(static_cast<std::size_t>(w + 1) * h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) rows += checkerboard && (x + y) % 2 ? '@' : '.';
    rows += '\n';
  }
  return mapText(w, h, rows);
}

// A URDF robot whose links form one chain of `links` (each fixed to the one before).
std::string chainUrdf(int links) {
  std::string u = "<robot name=\"chain\">\n";
  const std::string inertial =
      "<inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" "
      "ixz=\"0\" iyz=\"0\"/></inertial>";
  for (int i = 0; i < links; ++i) {
    u += "<link name=\"l" + std::to_string(i) + "\">" + inertial + "</link>\n";
    if (i > 0)
      u += "<joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"l" +
           std::to_string(i - 1) + "\"/><child link=\"l" + std::to_string(i) + "\"/></joint>\n";
  }
  return u + "</robot>\n";
}

// A small world for one ground robot of `model` (a file beside the scenario, or a bundled name).
std::string robotScenario(const std::string& model, const std::string& world_extra = "") {
  return "world: {bounds: {min: [0, 0, 0], max: [20, 20, 3]}" + world_extra +
         "}\nvehicles: [{name: r, model: " + model + ", start: [2, 2, 0], goal: [18, 2, 0]}]\n";
}

// A run folder as cosim run leaves it, with a time series of the given rows (after the header).
std::vector<std::pair<std::string, std::string>> runFolder(const std::string& rows) {
  return {
      {"run/scenario.yaml", kValid},
      {"run/run.json", "{\"scenario_file\": \"run/scenario.yaml\"}\n"},
      {"run/path.csv", "x,y,z\n2,2,1\n18,18,1\n"},
      {"run/timeseries.csv", "t,ref_x,ref_y,ref_z,x,y,z,vx,vy,vz,qw,qx,qy,qz,vehicle\n" + rows}};
}

// 10 000 tiny spheres high up, and a vehicle with 25 000 waypoints below them: 2.5e8 checks.
std::string manyPointsTimesObstacles() {
  std::string y = "world:\n  bounds: {min: [0, 0, 0], max: [200, 200, 10]}\n  obstacles:\n";
  for (int i = 0; i < 10000; ++i)
    y += "    - {type: sphere, pos: [" + std::to_string(1 + (i % 100) * 1.9) + ", " +
         std::to_string(1 + (i / 100) * 1.9) + ", 9], radius: 0.01}\n";
  y += "vehicles:\n  - name: uav1\n    model: cf2\n    start: [1, 1, 1]\n    waypoints:\n";
  for (int i = 0; i < 25000; ++i)
    y += "      - [" + std::to_string(1 + i % 190) + ", " + std::to_string(1 + i / 190 % 190) +
         ", 1]\n";
  return y + "planner: {name: astar, resolution: 0.5}\n";
}

// A moving obstacle's path of 2000 points, shared through an alias by 1000 obstacles.
std::string aliasSharedMovingPath() {
  std::string y = "world:\n  bounds: {min: [0, 0, 0], max: [100, 100, 3]}\n  moving_obstacles:\n";
  y += "    - {type: cylinder, radius: 0.2, height: 1, speed: 1, path: &p [";
  for (int i = 0; i < 2000; ++i)
    y += (i ? ", [" : "[") + std::to_string(50 + (i % 40)) + ", " + std::to_string(50 + i / 40) +
         "]";
  y += "]}\n";
  for (int i = 1; i < 1000; ++i)
    y += "    - {type: cylinder, radius: 0.2, height: 1, speed: 1, path: *p}\n";
  return y + "vehicles: [{name: r, model: omni_base, start: [2, 2, 0], goal: [18, 2, 0]}]\n";
}

// The valid scenario's vehicle flying `reference` instead of its goal.
std::string withReference(const std::string& reference) {
  return withVehicles(
      "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], reference: " + reference + "}]\n");
}

// A uav_trajectories file whose one piece lasts `duration` (all coefficients zero).
std::string polynomialReference(const std::string& duration) {
  std::string text = "duration";
  for (const char* axis : {"x", "y", "z", "yaw"})
    for (int k = 0; k < 8; ++k) text += std::string(",") + axis + "^" + std::to_string(k);
  text += "\n" + duration;
  for (int i = 0; i < 32; ++i) text += ",0";
  return text + "\n";
}

// A sampled reference of `rows` rows, 10 ms apart, standing still.
std::string manySamples(int rows) {
  std::string text = "t,x,y,z\n";
  for (int i = 0; i < rows; ++i) text += std::to_string(i * 0.01) + ",0,0,0\n";
  return text;
}

std::vector<BadInput> badInputs() {
  const std::string plan = "plan {in} --out {out}";
  const std::string run = "run {in} --no-video --out {out}";
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
       "needs a 'goal', 'waypoints' or a 'reference'"},
      // A given reference (vehicles[i].reference): bad files named with their line, misuses.
      {"reference_unknown_header",
       run,
       withReference("{file: ref.csv}"),
       "",
       2,
       "{dir}/ref.csv: line 1: unknown header 'time,x,y,z'",
       {{"ref.csv", "time,x,y,z\n0,0,0,0\n1,1,0,0\n"}}},
      {"reference_times_going_back",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 4, column t: time 0.5 is not after the previous row's 1",
       {{"ref.csv", "t,x,y,z\n0,0,0,0\n1,1,0,0\n0.5,1,1,0\n"}}},
      {"reference_nan",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 3, column y: 'NaN' is not a finite number",
       {{"ref.csv", "t,x,y,z\n0,0,0,0\n1,1,NaN,0\n"}}},
      {"reference_zero_duration",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 2, column duration: duration 0 s is not > 0",
       {{"ref.csv", polynomialReference("0")}}},
      {"reference_row_too_short",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 3: 3 values, expected 33 (as the header)",
       {{"ref.csv", polynomialReference("1") + "1,0,0\n"}}},
      {"reference_empty_file",
       run,
       withReference("{file: ref.csv}"),
       "",
       2,
       "{dir}/ref.csv: line 1: empty file",
       {{"ref.csv", ""}}},
      {"reference_too_many_rows",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 100003: more than 100000 intervals between samples",
       {{"ref.csv", manySamples(100002)}}},
      {"reference_and_goal",
       run,
       withVehicles("vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1],\n"
                    "             reference: {file: ref.csv}}]\n"),
       "",
       2,
       "key vehicles[0].goal: a vehicle with a 'reference' flies it instead of a goal",
       {{"ref.csv", "t,x,y,z\n0,2,2,1\n1,3,2,1\n"}}},
      {"reference_missing_file", run, withReference("{file: none.csv}"), "", 2,
       "key vehicles[0].reference.file: {dir}/none.csv: "},
      {"reference_and_team_planner_for_some",
       run,
       kWorld + "vehicles: [{name: a, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]},\n"
                "           {name: b, model: cf2, start: [2, 5, 1], reference: {file: ref.csv,\n"
                "            relative: true}}]\nplanner: {name: cbs}\n",
       "",
       2,
       "vehicles[1].reference: team planner 'cbs' plans every quadrotor together: give every "
       "vehicle a reference, or none",
       {{"ref.csv", "t,x,y,z\n0,0,0,0\n1,1,0,0\n"}}},
      // Planner, trajectory, controller, simulation settings.
      {"unknown_planner", plan, withPlanner("planner: {name: teleport}\n"), "", 2,
       "unknown planner 'teleport'"},
      {"misspelt_planner_parameter", plan, withPlanner("planner: {name: astar, resolutoin: 0.5}\n"),
       "", 2,
       "{in}: line 4, key planner.resolutoin: unknown parameter 'resolutoin' for planner 'astar' "
       "(did you mean 'resolution'? allowed: "},
      // Planner errors come before the output folder and the "planning ... with" progress line
      // (one stderr line), at the line of planner.name, with a "did you mean" for near misses.
      {"planner_name_near_miss", "run {in} --no-video --out {dir}/new",
       withPlanner("planner: {name: thetastar}\n"), "", 2,
       "{in}: line 4, key planner.name: unknown planner 'thetastar' (did you mean 'theta_star'? "
       "known: "},
      {"plan_with_a_team_planner", "plan {in} --planner cbs --out {dir}/new", kValid, "", 2,
       "{in}: --planner cbs: 'cbs' is a team (multi-robot) planner, not a single-agent planner: "
       "team planners are for `cosim mapf` and for `cosim run` on a scenario of ground robots or "
       "of a quadrotor team"},
      {"saco_start_and_goal_at_different_heights", "plan {in} --out {dir}/new",
       kWorld + "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1.2], goal: [18, 18, 3.2]}]\n" +
           "planner: {name: saco, resolution: 0.5}\n",
       "", 1,
       "start and goal must be at the same height, in one layer of the 0.5 m grid (start in z "
       "1-1.5 "
       "m, goal in z 3-3.5 m)"},
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
       "must be 'cascade', 'geometric', 'indi', 'dsl_pid', 'crazyflie_lee', 'crazyflie_mellinger' "
       "or "
       "'crazyflie_pid'"},
      {"drag_compensation_on_cascade", plan,
       kValid + "controller: {name: cascade, drag_compensation: true}\n", "", 2,
       "controller.drag_compensation: applies to the 'geometric' and 'indi' controllers"},
      // Sensing, estimation, aerodynamics (the realism issue).
      {"unknown_sensor_preset", plan, kValid + "sensors: {preset: lidar}\n", "", 2,
       "key sensors.preset: unknown preset 'lidar' (ideal, mocap, onboard)"},
      {"negative_sensor_noise", plan,
       kValid + "sensors: {preset: mocap, position: {noise: -0.1}}\n", "", 2,
       "key sensors.position.noise: must be >= 0"},
      {"latency_longer_than_run", plan,
       kValid + "sensors: {preset: mocap, attitude: {latency: 0.5}}\nsim: {max_time: 0.3}\n", "", 2,
       "key sensors.attitude.latency: latency 0.5 s is longer than the run"},
      {"ekf_without_sensors", plan, kValid + "estimator: {name: ekf}\n", "", 2,
       "key estimator.name: 'ekf' needs sensors to fuse"},
      {"ekf_without_position_sensor", plan,
       kValid + "sensors: {imu: {rate: 500}}\nestimator: {name: ekf}\n", "", 2,
       "key estimator.name: 'ekf' needs a position sensor"},
      {"predict_rate_zero", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ekf, predict_rate: 0}\n", "", 2,
       "key estimator.predict_rate"},
      {"predict_rate_without_ekf", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ground_truth, predict_rate: 50}\n", "",
       2, "key estimator.predict_rate: only the ekf predicts"},
      {"sensor_faster_than_physics", plan, kValid + "sensors: {preset: mocap, imu: {rate: 5000}}\n",
       "", 2, "key sensors.imu.rate: rate 5000 Hz is above the physics rate"},
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
       "{in}: --set wrld.x=1, key wrld: unknown key 'wrld' (did you mean 'world'? allowed: "},
      // --set on list elements: an index past the end, or into something that is not a list.
      {"set_list_index_out_of_range", "plan {in} --set 'vehicles[3].goal=[5,5,1]' --out {dir}/new",
       kValid, "", 2,
       "command line: --set vehicles[3].goal=[5,5,1]: index 3 is out of range: vehicles has 1 "
       "element (indices 0 to 0)"},
      {"set_index_into_a_mapping", "plan {in} --set 'planner[0].name=rrt' --out {dir}/new", kValid,
       "", 2, "--set planner[0].name=rrt: planner is not a list, so it has no element planner[0]"},
      {"set_malformed_index", "plan {in} --set 'vehicles[x].goal=[5,5,1]' --out {dir}/new", kValid,
       "", 2, "'vehicles[x]': a list element is written name[N], N a whole number from 0"},
      {"set_list_element_bad_value", "plan {in} --set 'vehicles[0].goal=[5,5]' --out {dir}/new",
       kValid, "", 2,
       "{in}: --set vehicles[0].goal=[5,5], key vehicles[0].goal: must be a list of 3 numbers"},
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
      // Hardening, round two: what an adversarial probe broke.
      // YAML structure: alias cycles, alias bombs, keys given twice (at any level).
      {"alias_cycle_in_scenario", plan, kValid + "sim: &s {timestep: *s}\n", "", 2,
       "line 5, key sim.timestep: an alias refers to a node that contains it"},
      {"alias_cycle_in_set_value", "plan {in} --set 'sim=&a [*a]' --out {out}", kValid, "", 2,
       "--set sim=&a [*a]: an alias refers to a node that contains it"},
      {"alias_bomb", plan,
       kValid +
           [] {
             std::string b = "render: {l0: &l0 [x, x, x, x, x, x, x, x, x, x]";
             for (int i = 1; i <= 8; ++i) {
               const std::string p = "*l" + std::to_string(i - 1);
               b += ", l" + std::to_string(i) + ": &l" + std::to_string(i) + " [" + p + ", " + p +
                    ", " + p + ", " + p + ", " + p + ", " + p + ", " + p + ", " + p + ", " + p +
                    ", " + p + "]";
             }
             return b + "}\n";
           }(),
       "", 2, "values once its aliases are expanded"},
      {"alias_shared_moving_obstacle_path", "run {in} --no-video --out {out}",
       aliasSharedMovingPath(), "", 2, "values once its aliases are expanded"},
      {"duplicate_top_level_key", plan, kValid + "planner: {name: rrt}\n", "", 2,
       "line 5, key planner: key 'planner' is given twice in this mapping"},
      {"duplicate_nested_key", plan,
       withPlanner("planner: {name: astar, resolution: 0.5, "
                   "resolution: 0.25}\n"),
       "", 2, "key planner.resolution: key 'resolution' is given twice"},
      // Sweeps: a self-referencing `set:` (a crash in the flattener), an unsafe name, a world
      // generator asked for 50 million trees.
      {"sweep_set_alias_cycle",
       "sweep {in} --out {out} --quiet",
       "scenarios: [s.yaml]\nset: &s {a: *s}\n",
       "",
       2,
       "key set.a: an alias refers to a node that contains it",
       {{"s.yaml", kValid}}},
      {"sweep_set_alias_cycle_merge_only",
       "sweep {in} --out {out} --merge-only --quiet",
       "scenarios: [s.yaml]\nset: &s {a: *s}\n",
       "",
       2,
       "key set.a: an alias refers to a node that contains it",
       {{"s.yaml", kValid}}},
      {"sweep_unsafe_name",
       "sweep {in} --quiet",
       "name: ../../../escaped\nscenarios: [s.yaml]\n",
       "",
       2,
       "key name: '../../../escaped' cannot name the sweep's folder: starts with '.'",
       {{"s.yaml", kValid}}},
      {"sweep_forest_of_10_km", "sweep {in} --out {out} --quiet",
       "generators: [{type: forest, density: 0.5, size: [10000, 10000, 10]}]\n", "", 2,
       "obstacles, more than the 10000 a scenario may hold"},
      // Files that are not files: a device read forever, a FIFO that blocks.
      {"scenario_is_dev_zero", "plan /dev/zero --out {out}", "", "", 2,
       "/dev/zero: is not a regular file"},
      {"scenario_is_fifo",
       "plan {dir}/pipe.yaml --out {out}",
       "",
       "",
       2,
       "pipe.yaml: is not a regular file",
       {},
       "pipe.yaml"},
      {"include_is_fifo",
       "run {in} --no-video --out {out}",
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: pipe.xml}\n"),
       "",
       2,
       "key world.include: {dir}/pipe.xml: is not a regular file",
       {},
       "pipe.xml"},
      // Names: a documented character set and length.
      {"vehicle_name_with_newline", plan,
       withVehicles(
           "vehicles: [{name: \"a\\nb\", model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n"),
       "", 2, "vehicles[0].name: vehicle names are printable ASCII without spaces or '/'"},
      {"vehicle_name_of_200_kb", plan,
       withVehicles("vehicles: [{name: " + std::string(200000, 'n') +
                    ", model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n"),
       "", 2, "a vehicle name has at most 64 characters"},
      // Limits before allocation for what a small file multiplies.
      {"grid_map_checkerboard",
       "run {in} --no-video --out {out}",
       "world: {grid_map: {file: checker.map, cell: 0.1}}\n"
       "vehicles: [{name: r, model: omni_base, start: [0.05, 0.05, 0], goal: [0.25, 0.05, 0]}]\n",
       "",
       2,
       "key world.grid_map.file: the map's blocked cells make more than 10000 boxes",
       {{"checker.map", wideMap(1000, 1000, true)}}},
      {"points_times_obstacles", plan, manyPointsTimesObstacles(), "", 2,
       "placement checks, more than 200000000"},
      {"mapf_agents_times_cells", "mapf {in} {in2} --agents 100 --planner hca_star --out {out}",
       wideMap(2000, 2000, false),
       [] {
         std::string scen = "version 1\n";
         for (int i = 0; i < 100; ++i)
           scen += "0\tx.map\t2000\t2000\t" + std::to_string(i) + "\t0\t" + std::to_string(i) +
                   "\t1999\t2000\n";
         return scen;
       }(),
       2, "1907 MB (100 agents x 4000000 cells x 5 bytes), more than the 1024 MB"},
      {"planner_time_limit_of_a_day", plan,
       withPlanner("planner: {name: astar, resolution: 0.5, time_limit: 86400}\n"), "", 2,
       "'time_limit' = 86400 is outside [0.001, 3600]"},
      // URDF robots of a 20 000-link chain (a crash: one recursion per link) and a deep one.
      {"urdf_chain_of_20000_links",
       "run {in} --no-video --out {out}",
       robotScenario("chain.urdf"),
       "",
       2,
       "chain.urdf: line 2001, <link>: more than 1000 links",
       {{"chain.urdf", chainUrdf(20000)}}},
      {"urdf_chain_deeper_than_64",
       "run {in} --no-video --out {out}",
       robotScenario("deep.urdf"),
       "",
       2,
       "deep.urdf: link 'l65': more than 64 links below the base on one branch",
       {{"deep.urdf", chainUrdf(100)}}},
      {"urdf_joints_form_a_loop",
       "run {in} --no-video --out {out}",
       robotScenario("loop.urdf"),
       "",
       2,
       "loop.urdf: line 4, <joint>: link 'a' is its own ancestor (the joints form a loop",
       {{"loop.urdf",
         "<robot name=\"loop\">\n<link name=\"a\"/><link name=\"b\"/>\n"
         "<joint name=\"ab\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
         "<joint name=\"ba\" type=\"fixed\"><parent link=\"b\"/><child link=\"a\"/></joint>\n"
         "</robot>\n"}}},
      // world.include: the scenario owns the physics options; sizes are bounded; errors name the
      // fragment.
      {"include_sets_timestep",
       "run {in} --no-video --out {out}",
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: frag.xml}\n"),
       "",
       2,
       "frag.xml: line 2, <option>: a world fragment may not set the world's <option>",
       {{"frag.xml", "<mujoco>\n  <option timestep=\"0.01\"/>\n</mujoco>\n"}}},
      {"include_height_field_38000_squared",
       "run {in} --no-video --out {out}",
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: frag.xml}\n"),
       "",
       2,
       "frag.xml: line 1, <hfield>: a height field of 38000 x 38000",
       {{"frag.xml",
         "<mujoco><asset><hfield name=\"h\" nrow=\"38000\" ncol=\"38000\" "
         "size=\"1 1 1 1\"/></asset></mujoco>\n"}}},
      {"include_error_names_the_fragment",
       "run {in} --no-video --out {out}",
       withWorld("world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: frag.xml}\n"),
       "",
       2,
       "frag.xml: MuJoCo cannot compile this world fragment (world.include): ",
       {{"frag.xml",
         "<mujoco>\n<worldbody>\n<geom type=\"pyramid\" size=\"1\"/>\n"
         "</worldbody>\n</mujoco>\n"}}},
      // Options: NaN is not a number; 0 agents is one clear line.
      {"mapf_time_limit_nan",
       "mapf {in} {in2} --agents 1 --planner cbs --time-limit nan --out {out}", map8, scen8, 2,
       "--time-limit: must be a number from 0.001 to 3600, got 'nan'"},
      {"mapf_cell_nan", "mapf {in} {in2} --agents 1 --planner cbs --execute --cell nan --out {out}",
       map8, scen8, 2, "--cell: must be a number from 0.05 to 100, got 'nan'"},
      {"mapf_zero_agents", "mapf {in} {in2} --agents 0 --planner cbs --out {out}", map8, scen8, 2,
       "--agents: must be a whole number from 1 to 10000, got '0'"},
      // Output paths checked before any work; names of 254 bytes are valid.
      {"grid_bench_out_in_missing_folder",
       "grid-bench {in} {in2} --planner astar --out /nonexistent/x.csv", map8, scen8, 2,
       "/nonexistent/x.csv: --out: folder /nonexistent does not exist"},
      {"render_out_in_missing_folder", "render {dir}/run --out {dir}/missing/v.mp4 --quiet", "", "",
       2, "--out: folder {dir}/missing does not exist",
       runFolder("0,2,2,1,2,2,1,0,0,0,1,0,0,0,uav1\n1,3,3,1,3,3,1,0,0,0,1,0,0,0,uav1\n")},
      {"render_log_row_at_1e9_s", "render {dir}/run --out {dir}/v.mp4 --quiet", "", "", 2,
       "timeseries.csv: line 3, column t: time 1000000000.000000 s is outside the run",
       runFolder("0,2,2,1,2,2,1,0,0,0,1,0,0,0,uav1\n1e9,3,3,1,3,3,1,0,0,0,1,0,0,0,uav1\n")},
      {"out_file_name_of_254_bytes",
       "grid-bench {in} {in2} --planner astar --out {dir}/" + std::string(250, 'x') + ".csv", map8,
       scen8, 0, "written:"},
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
  for (const auto& [name, content] : c.files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << content;
  }
  if (!c.fifo.empty()) {
    ASSERT_EQ(::mkfifo((dir / c.fifo).c_str(), 0644), 0);
  }
  const bool is_map = c.args.rfind("grid-bench", 0) == 0 || c.args.rfind("mapf", 0) == 0;
  const fs::path in = dir / (is_map ? "x.map" : "scenario.yaml");
  const fs::path in2 = dir / "x.scen";
  std::ofstream(in, std::ios::binary) << c.content;
  std::ofstream(in2, std::ios::binary) << c.content2;
  // The output folder exists (as after an earlier run): what a command may leave there is checked
  // below, and a command writing a file into it (grid-bench) finds it.
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::string args = replaceAll(c.args, "{in}", in.string());
  args = replaceAll(args, "{in2}", in2.string());
  args = replaceAll(args, "{out}", out.string());
  args = replaceAll(args, "{dir}", dir.string());

  // Never a hang (the watchdog ends the program at 60 s: exit 124 or 137) and never more than
  // 1 GB of memory (the largest resident size of any program this test process has waited for;
  // ctest runs each case in a process of its own).
  const CommandResult r = runCosim(args, dir, 60);
  EXPECT_EQ(r.status, c.exit_code) << args << "\nstderr: " << r.err << "\nstdout: " << r.out;
  struct rusage usage {};
  ::getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 1024L * 1024L) << "KiB resident at most";  // ru_maxrss is in KiB
  // The program's own message, never a crash report or an internal error.
  const std::string all = r.err + r.out;
  const std::string message =
      replaceAll(replaceAll(c.message, "{in}", in.string()), "{dir}", dir.string());
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
    // A case writing to {dir}/new (a folder that does not exist yet) must not create it.
    EXPECT_FALSE(fs::exists(dir / "new")) << "bad input created its output folder";
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
