// What an adversarial probe broke: YAML alias cycles and bombs, keys given twice, sweeps asking
// for too much, files that are devices or FIFOs, names of any length, inputs that multiply into
// billions of checks or cells, URDF chains and loops, world fragments, NaN options and output
// paths.
#include <string>
#include <vector>

#include "tests/cli/bad_input_case.h"

namespace cosim::test {

namespace {

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

}  // namespace

std::vector<BadInput> hardeningBadInputs() {
  const std::string& plan = kPlanCommand;
  const std::string& scen8 = kScen8;
  const std::string map8 = freeMap8();
  return {
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
      // Small items of the third probe. Controller gains are checked before planning (they were
      // read after a 20 s rrt_star search): bad input before the output folder is made.
      {"controller_gain_misspelt_before_planning", "run {in} --no-video --out {dir}/new",
       kWorld + kVehicle + "planner: {name: rrt_star, time_limit: 20}\n" +
           "controller: {name: cascade, gains: {pos_kpp: 1}}\n",
       "", 2,
       "line 5, key controller.gains.pos_kpp: unknown parameter 'pos_kpp' for controller "
       "'cascade' (did you mean 'pos_kp'?"},
      {"controller_gain_out_of_range_before_planning", "run {in} --no-video --out {dir}/new",
       kWorld + kVehicle + "planner: {name: rrt_star, time_limit: 20}\n" +
           "controller: {name: cascade, gains: {pos_kp: 1000}}\n",
       "", 2, "line 5, key controller.gains.pos_kp: 'pos_kp' = 1000 is outside [0, 100]"},
      {"ground_gain_misspelt_before_planning", "run {in} --no-video --out {dir}/new",
       robotScenario("omni_base") + "planner: {name: astar, resolution: 0.5}\n" +
           "controller: {gains: {k_positoin: 1}}\n",
       "", 2,
       "line 4, key controller.gains.k_positoin: unknown parameter 'k_positoin' for "
       "controller.gains (ground robots) (did you mean 'k_position'?"},
      // A believed mass of 0 or below silently meant the airframe's; 1e-300 was taken.
      {"controller_mass_zero", "run {in} --no-video --out {dir}/new",
       withPlanner("controller: {name: crazyflie_lee, gains: {mass: 0}}\n"), "", 2,
       "key controller.gains.mass: 'mass' = 0 is outside [0.01, 100]"},
      {"controller_mass_negative", "run {in} --no-video --out {dir}/new",
       withPlanner("controller: {name: crazyflie_mellinger, gains: {mass: -0.5}}\n"), "", 2,
       "key controller.gains.mass: 'mass' = -0.5 is outside [0.01, 100]"},
      {"controller_mass_1e_minus_300", "run {in} --no-video --out {dir}/new",
       withPlanner("controller: {name: crazyflie_lee, gains: {mass: 1e-300}}\n"), "", 2,
       "'mass' = 1e-300 is outside [0.01, 100]"},
      // `..` was refused but a trailing dot set the key before it.
      {"set_trailing_dot", "plan {in} --set 'vehicles[0].name.=x' --out {dir}/new", kValid, "", 2,
       "--set vehicles[0].name.=x: empty key in path 'vehicles[0].name.'"},
      // A value of 100 kB echoed whole in the message: the place and the value are cut short.
      {"set_value_of_100_kb_not_echoed",
       "plan {in} --set planner.resolution=" + std::string(100000, 'x') + " --out {dir}/new",
       kValid, "", 2,
       "--set planner.resolution=" + std::string(61, 'x') +
           "..., key planner.resolution: 'resolution' must be a number, got '" +
           std::string(80, 'x') + "...'"},
      // yaml-cpp reads the first document: what followed '---' was silently ignored.
      {"second_yaml_document", plan, kValid + "---\nvehicles: []\n", "", 2,
       "scenario.yaml: line 5: a second YAML document (after '---')"},
      {"out_file_name_of_254_bytes",
       "grid-bench {in} {in2} --planner astar --out {dir}/" + std::string(250, 'x') + ".csv", map8,
       scen8, 0, "written:"},
  };
}

}  // namespace cosim::test
