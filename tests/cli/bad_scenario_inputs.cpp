// Bad scenario contents: malformed, truncated or empty files; wrong types, huge numbers and NaN in
// the world; overlapping, outside or missing vehicles; bad given references; unknown planners,
// controllers and sensors; impossible simulation settings; and the tasks that fail (exit 1).
#include <string>
#include <vector>

#include "tests/cli/bad_input_case.h"

namespace cosim::test {

namespace {

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

}  // namespace

std::vector<BadInput> badScenarioInputs() {
  const std::string& plan = kPlanCommand;
  const std::string& run = kRunCommand;
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
       "", 2, "inside world.obstacles[0]"},
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
       "{dir}/ref.csv: line 3, column y: 'NaN' is not a decimal number",
       {{"ref.csv", "t,x,y,z\n0,0,0,0\n1,1,NaN,0\n"}}},
      // strtod reads hexadecimal: 0x10 was flown as 16.
      {"reference_hexadecimal",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 3, column x: '0x10' is not a decimal number",
       {{"ref.csv", "t,x,y,z\n0,0,0,0\n1,0x10,0,0\n"}}},
      // Any readable file may be named: its first line is quoted short, its bytes escaped.
      {"reference_binary_file",
       run,
       withReference("{file: ref.csv, relative: true}"),
       "",
       2,
       "{dir}/ref.csv: line 1: unknown header '\\x89PNG\\x1a\\xff\\xfe" + std::string(33, 'A') +
           "...'",
       {{"ref.csv", "\x89PNG\x1a\xff\xfe" + std::string(300, 'A') + "\n"}}},
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
       "key sensors.position.noise: = -0.1 is outside [0, 1e+06]"},
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
       2, "key estimator.predict_rate: only a filter predicts"},
      {"fuse_unknown_timing", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ekf, fuse: late}\n", "", 2,
       "key estimator.fuse: must be 'at_validity' or 'on_arrival'"},
      {"fuse_without_ekf", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ground_truth, fuse: on_arrival}\n", "",
       2, "key estimator.fuse: only a filter fuses"},
      {"crazyflie_kalman_without_sensors", plan, kValid + "estimator: {name: crazyflie_kalman}\n",
       "", 2, "key estimator.name: 'crazyflie_kalman' needs sensors to fuse"},
      {"crazyflie_kalman_at_validity", plan,
       kValid +
           "sensors: {preset: mocap}\nestimator: {name: crazyflie_kalman, fuse: at_validity}\n",
       "", 2, "key estimator.fuse: crazyflie_kalman fuses each fix when it arrives"},
      {"crazyflie_kalman_predict_rate_above_its_loop", plan,
       kValid +
           "sensors: {preset: mocap}\nestimator: {name: crazyflie_kalman, predict_rate: 2000}\n",
       "", 2, "key estimator.predict_rate"},
      {"drag_without_crazyflie_kalman", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ekf, drag: [1, 1, 0]}\n", "", 2,
       "key estimator.drag: only crazyflie_kalman has a drag term"},
      {"crazyflie_kalman_negative_drag", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: crazyflie_kalman, drag: [-1, 0, 0]}\n",
       "", 2, "key estimator.drag: each component must be in [0, 100]"},
      {"attitude_std_beyond_pi", plan,
       kValid + "sensors: {preset: mocap}\nestimator: {name: ekf, attitude_std: 4}\n", "", 2,
       "key estimator.attitude_std"},
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
  };
}

}  // namespace cosim::test
