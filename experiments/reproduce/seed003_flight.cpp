// Seed 003 revisited (Navratil 2019, sec. 4.2): its quadrotor flew a Basic Theta* path and an
// RRT*FN path on 3D map 3 by feeding the raw waypoints as position set-points (switching to the
// next within 0.2 m), and the flight left the plan and went into obstacles; the thesis names the
// cause (vehicle size and dynamics ignored) and leaves the fix to future work. Here both paths
// are flown the thesis's way and ours, in MuJoCo:
//  - thesis: planned for a point mass on the thesis's own terms (Theta* on 1 m cells blocked only
//    when their centre is inside an obstacle; the thesis's RRT*FN with its sampling-table
//    settings), raw waypoints, 0.2 m switching, the cascade controller of its Fig. 2;
//  - grown_waypoints: the plan grown by the vehicle's radius plus a margin, still raw waypoints;
//  - cosim: the grown plan, a minimum-snap trajectory, the geometric controller.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/json_reading.h"
#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/reproduction.h"
#include "experiments/reproduce/reproduction_map.h"
#include "experiments/reproduce/seed003_maps.h"
#include "run/run_pipeline.h"

namespace cosim::reproduce {

namespace {

struct Pipeline {
  const char* name;   // seed003-flight.json's "pipeline"
  const char* label;  // the report's
  std::vector<std::string> overrides;
  bool point_mass;
};

struct PathSetting {
  const char* name;            // "theta_star" | "rrt_star_fn"
  std::string thesis_planner;  // the thesis's planner and settings (point mass)
  std::string cosim_planner;   // ours (grown by radius + margin)
};

std::string fmt(double v, int decimals = 3) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << v;
  return s.str();
}

// The planned path (path.csv of the run) and its closest approach to an obstacle surface, for a
// point (sampled every 2 cm): <= 0 means the plan itself touches or enters an obstacle.
double planClearance(const std::filesystem::path& path_csv, const World& world) {
  std::ifstream in(path_csv);
  std::string line;
  std::getline(in, line);  // header x,y,z
  std::vector<Eigen::Vector3d> points;
  while (std::getline(in, line)) {
    Eigen::Vector3d p;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &p.x(), &p.y(), &p.z()) == 3) points.push_back(p);
  }
  double clearance = INFINITY;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const int steps = std::max(1, static_cast<int>((points[i + 1] - points[i]).norm() / 0.02));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector3d p = points[i] + (points[i + 1] - points[i]) * (double(k) / steps);
      for (const Obstacle& o : world.obstacles)
        clearance = std::min(clearance, o.signedDistance(p));
    }
  }
  return clearance;
}

// The planned polyline of a run (its path.csv, x,y,z per line), seen from above.
std::vector<Eigen::Vector2d> plannedPoints(const std::filesystem::path& path_csv) {
  std::ifstream in(path_csv);
  std::string line;
  std::getline(in, line);  // header
  std::vector<Eigen::Vector2d> points;
  while (std::getline(in, line)) {
    double x, y, z;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &x, &y, &z) == 3) points.emplace_back(x, y);
  }
  return points;
}

// The flown track of a run (its timeseries.csv, columns x and y), seen from above, every 20th
// sample (a few centimetres apart at these speeds).
std::vector<Eigen::Vector2d> flownPoints(const std::filesystem::path& timeseries_csv) {
  std::ifstream in(timeseries_csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream h(line); std::getline(h, line, ',');) header.push_back(line);
  const auto column = [&](const char* name) {
    return std::find(header.begin(), header.end(), name) - header.begin();
  };
  const auto ix = column("x"), iy = column("y");
  std::vector<Eigen::Vector2d> points;
  for (int row = 0; std::getline(in, line); ++row) {
    if (row % 20) continue;
    std::vector<double> v;
    for (std::stringstream c(line); std::getline(c, line, ',');)
      v.push_back(std::atof(line.c_str()));
    if (static_cast<std::size_t>(std::max(ix, iy)) < v.size()) points.emplace_back(v[ix], v[iy]);
  }
  return points;
}

// One figure per way of flying (the thesis's, ours): both paths' plans and flights, as the
// thesis's Figs. 39-40 set the flown track against the plan.
std::string flightMap(const Options& options,
                      const std::map<std::string, std::vector<MapPath>>& drawn) {
  const Seed003Map map = seed003Maps().back();  // 3D map 3
  const OccupancyGrid grid = seed003Grid(map);
  std::vector<std::string> files, how;
  for (const char* pipeline : {"thesis", "cosim"}) {
    const auto it = drawn.find(pipeline);
    if (it == drawn.end()) continue;
    ReproductionMap fig = gridMap(
        std::string("3D map 3 seen from above: ") + pipeline + " pipeline, plans and flights", grid,
        grid.cellOf(map.start), grid.cellOf(map.goal));
    fig.unit = "m";
    fig.paths = it->second;
    files.push_back(writeReproductionMap(options.out_dir, "seed003-flight",
                                         static_cast<int>(files.size()) + 1, fig));
    how.push_back(std::string(pipeline) +
                  " pipeline on 3D map 3 (an equivalent rebuilt from the thesis's figure only: "
                  "size, start, goal and description from the text; the boxes of "
                  "experiments/scenarios/zigzag_walls.yaml), each path's plan and its flight");
  }
  return mapFiguresMarkdown(files, how);
}

// How the run ended ("goal", "max_time", "saturated", ...): metrics.json's end_reason.
// The two planners' settings: the thesis's point-mass plan and ours.
std::vector<PathSetting> flightPaths() {
  // RRT*FN: parameter set 4 with cap 400 (step 4 m, radius 6 m, 2000 nodes, mode 2: its Tab. 17,
  // the settings it recommends and flies) and the sampling tables' goal settings (no goal bias,
  // the goal reached from within one step; cosim reproduce seed003-sampling).
  const std::string fn_settings =
      "step: 4, rewire_radius: 6, max_nodes: 2000, max_tree_nodes: 400, mode: 2, goal_bias: 0, "
      "goal_tolerance: 4";
  return {
      {"theta_star", "planner={name: theta_star, resolution: 1.0, cell_blocking: centre}",
       "planner={name: theta_star, resolution: 0.5, margin: 0.3}"},
      {"rrt_star_fn", "planner={name: rrt_star_thesis, " + fn_settings + "}",
       "planner={name: rrt_star_fn, " + fn_settings + ", margin: 0.3}"},
  };
}

// The four ways of flying each plan.
std::vector<Pipeline> flightPipelines() {
  return {
      {"thesis",
       "thesis: point-mass plan, raw waypoints (0.2 m), cascade",
       {"trajectory={mode: waypoints, switch_radius: 0.2}", "controller={name: cascade}"},
       true},
      {"grown_waypoints",
       "plan grown by radius + 0.3 m, raw waypoints (0.2 m), cascade",
       {"trajectory={mode: waypoints, switch_radius: 0.2}", "controller={name: cascade}"},
       false},
      {"cosim",
       "cosim: grown plan, minimum snap (3 m/s), geometric; ideal sensing, no disturbances",
       {"trajectory={mode: minimum_snap, max_speed: 3.0, max_acceleration: 3.0}",
        "controller={name: geometric}"},
       false},
      // experiments/scenarios/default.yaml's sensing and weather, the program's realistic case.
      {"cosim_realistic",
       "cosim with default.yaml's sensing and weather: mocap + EKF, rotor drag, wind 1.6 m/s, "
       "gusts 0.5 m/s",
       {"trajectory={mode: minimum_snap, max_speed: 3.0, max_acceleration: 3.0}",
        "controller={name: geometric}", "sensors={preset: mocap}", "estimator={name: ekf}",
        "disturbances={rotor_drag: true, wind: [1.5, 0.5, 0], gust: 0.5}"},
       false},
  };
}

// The report's opening: the map, the pipelines, where we differ, the table's header.
std::string flightIntroduction(const Options& options) {
  std::ostringstream md;
  md << "# Seed 003 revisited: flying the planned path on 3D map 3\n\n"
     << "Map 3 (50 x 50 x 5 m, start [3,2,2], goal [47,47,4]) as reconstructed in "
     << "`experiments/scenarios/zigzag_walls.yaml` (the thesis shows the layout only in a "
     << "figure; the same boxes as seed003-discrete's map 3d-3). quad_1500g (its bounding "
        "sphere, the body clearance's, in each flight's metrics.json: vehicle_radius_m), "
     << "MuJoCo at 1 kHz, control at 500 Hz, seed " << options.seed << "."
     << (options.quick ? " Quick run: every flight stops after 20 s, before the goal, so the "
                         "verdicts at the end need the full run."
                       : "")
     << "\n\n"
     << "**Pipelines.** `thesis` is the thesis's: the plan is for a point mass on the thesis's "
        "own terms, flown on its raw waypoints (next one within 0.2 m) by the cascade "
        "controller of its Fig. 2. For Theta* that means Basic Theta* on 1 m cells that are "
        "blocked only when their centre lies inside an obstacle (the thesis's grid: its vertices "
        "are cell centres), so the path may graze obstacle faces; it is the path of "
        "seed003-discrete's map 3 (78.19 m there). For RRT*FN it is the thesis's RRT*FN (its "
        "RRT* of Fig. 16 plus the cap) with the settings of its Tab. 17 (step 4 m, radius 6 m, "
        "N 2000, cap 400, mode 2) and of the sampling tables: no goal bias (an earlier version "
        "flew it with 0.05) and the goal reached from within one step, 4 m here, "
        "planned without inflation. `grown_waypoints` grows the obstacles by the vehicle's radius "
        "plus 0.3 m and keeps the raw waypoints; `cosim` is ours: the grown plan (Theta* on "
        "0.5 m cells, or our Karaman-Frazzoli RRT*FN with the same settings), a minimum-snap "
        "trajectory at up to 3 m/s and the geometric controller. The `cosim` rows fly with "
        "ideal sensing (the controller reads the exact state) and no disturbances, which is "
        "why their RMSE is a tenth of a millimetre; `cosim_realistic` flies the same plan with "
        "the sensing and weather of experiments/scenarios/default.yaml (motion capture fused by "
        "the EKF, rotor drag, a 1.6 m/s wind ([1.5, 0.5, 0] m/s) with 0.5 m/s gusts), the error "
        "to expect from a real vehicle. The `thesis` and `grown_waypoints` rows use ideal "
        "sensing too, as the thesis's Simulink model did.\n\n"
     << "Where we differ from the thesis: its start was [3,3,2] in the flight and [3,2,2] in the "
        "planning tables; we fly from [3,2,2] (the cell centre [2.5,1.5,1.5] m) for both. It "
        "used Peter Corke's Simulink quadrotor, whose parameters it does not give; ours is "
        "PX4's Iris (quad_1500g). The thesis reports no numbers for its flights, only that the "
        "flown path \"did not match much\" and went into obstacles (its Figs. 39-40).\n\n"
     << "Ended: `goal`, `max_time` (not there in time) or a fault such as `saturated` (the "
        "rotors saturated for 2 s: the vehicle is stuck against an obstacle). Error: for raw "
        "waypoints, the distance to the planned path (the reference jumps); for minimum snap, the "
        "distance to the reference trajectory at the same time. Plan clearance "
        "is the planned polyline's closest approach to an obstacle (a point); body clearance is "
        "the vehicle's bounding sphere's, negative when it intrudes.\n\n"
     << "| path | pipeline | planned [m] | plan clearance [m] | ended | collisions | RMSE [m] | "
        "max error [m] | body clearance [m] | flight time [s] |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  return md.str();
}

// What the findings need from all the flights.
struct FlightTally {
  bool thesis_intrudes_all = true, cosim_clean_all = true;
  int thesis_rows = 0, thesis_intruding = 0, cosim_rows = 0, cosim_clean = 0;
  double thesis_min_max_error = INFINITY;
  std::map<std::string, std::vector<MapPath>> drawn;  // per pipeline: plans and flights
};

// One path flown one way, in its folder flight<index>-<path>-<pipeline> under options.out_dir:
// a line of the table, a JSON row and the tally's share.
JsonObject flyOne(const Options& options, const PathSetting& path, const Pipeline& p, int index,
                  std::ostringstream& md, FlightTally& tally) {
  const std::string scenario_file = std::string(COSIM_SCENARIOS_DIR) + "/zigzag_walls.yaml";
  std::vector<std::string> overrides = {p.point_mass ? path.thesis_planner : path.cosim_planner};
  overrides.insert(overrides.end(), p.overrides.begin(), p.overrides.end());
  overrides.push_back("sim.seed=" + std::to_string(options.seed));
  if (options.quick) overrides.push_back("sim.max_time=20");
  Scenario scenario = loadScenario(scenario_file, overrides);
  RunRequest request;
  request.out_dir = std::filesystem::path(options.out_dir) /
                    ("flight" + std::to_string(index) + "-" + path.name + "-" + p.name);
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = !options.quick;
  request.plan_as_point_mass = p.point_mass;
  const RunRecord r = executeRun(scenario, request);
  const FlightMetrics& f = r.metrics.vehicles.front();
  const double plan_clearance = planClearance(request.out_dir / "path.csv", scenario.world);
  const std::string ended = runEndName(r.log.end_reason);
  const bool intrudes = f.collisions > 0 || f.min_clearance_m < 0.0;
  const std::string pipeline = p.name;
  if (pipeline == "thesis") {
    tally.thesis_intrudes_all &= intrudes;
    ++tally.thesis_rows;
    tally.thesis_intruding += intrudes;
    tally.thesis_min_max_error = std::min(tally.thesis_min_max_error, f.max_error_m);
  }
  if (pipeline.rfind("cosim", 0) == 0) {
    const bool clean = f.collisions == 0 && f.reached_goal;
    tally.cosim_clean_all &= clean;
    ++tally.cosim_rows;
    tally.cosim_clean += clean;
  }
  if (pipeline == "thesis" || pipeline == "cosim") {
    tally.drawn[pipeline].push_back(
        {std::string(path.name) + " plan (" + fmt(f.planned_length_m, 1) + " m)",
         plannedPoints(request.out_dir / "path.csv")});
    tally.drawn[pipeline].push_back(
        {std::string(path.name) + " flight (" + std::to_string(f.collisions) + " contacts)",
         flownPoints(request.out_dir / "timeseries.csv")});
  }
  md << "| " << path.name << " | " << p.label << " | " << fmt(f.planned_length_m, 2) << " | "
     << fmt(plan_clearance) << " | " << ended << " | " << f.collisions << " | " << fmt(f.rmse_m, 4)
     << " | " << fmt(f.max_error_m, 4) << " | " << fmt(f.min_clearance_m) << " | "
     << fmt(f.flight_time_s, 1) << " |\n";
  JsonObject row;
  row.add("path", path.name)
      .add("pipeline", p.name)
      .add("planned_length_m", f.planned_length_m)
      .add("plan_clearance_m", plan_clearance)
      .add("collisions", f.collisions)
      .add("reached_goal", f.reached_goal)
      .add("end_reason", ended)
      .add("min_clearance_m", f.min_clearance_m)
      .add("rmse_m", f.rmse_m)
      .add("max_error_m", f.max_error_m)
      .add("flight_time_s", f.flight_time_s)
      .add("status", r.exitStatus())
      .add("message", r.message);
  return row;
}

// The thesis's claims against the flights.
std::vector<Finding> flightFindings(const Options& options, const FlightTally& tally) {
  const bool thesis_intrudes_all = tally.thesis_intrudes_all;
  const bool cosim_clean_all = tally.cosim_clean_all;
  const int thesis_rows = tally.thesis_rows, thesis_intruding = tally.thesis_intruding;
  const int cosim_rows = tally.cosim_rows, cosim_clean = tally.cosim_clean;
  const double thesis_min_max_error = tally.thesis_min_max_error;
  std::vector<Finding> findings;
  findings.push_back(checkedFinding(
      "Flying the raw waypoints of a point-mass plan, the quadrotor intrudes into obstacles "
      "(Figs. 39-40; qualitative)",
      thesis_intrudes_all,
      "collisions or negative body clearance in " + std::to_string(thesis_intruding) + " of " +
          std::to_string(thesis_rows) + " `thesis` rows",
      "in the other `thesis` rows the vehicle stayed clear of the obstacles" +
          std::string(options.quick ? " in the 20 s a --quick flight lasts" : "") +
          "; the reconstructed map 3 and our vehicle are not the thesis's"));
  findings.push_back(checkedFinding(
      "The flown path deviates visibly from the plan (Figs. 39-40; qualitative)",
      thesis_min_max_error > 0.3,
      "smallest max error of the `thesis` rows " + fmt(thesis_min_max_error, 2) + " m",
      "our cascade controller follows the raw waypoints more closely than the thesis's Simulink "
      "model (whose parameters it does not give)"));
  findings.push_back(checkedFinding(
      "The cause is that the planners ignore the vehicle's size and dynamics (the fix left to "
      "future work)",
      cosim_clean_all,
      "planning with the vehicle's radius plus a margin and flying a minimum-snap trajectory: "
      "0 collisions and the goal reached in " +
          std::to_string(cosim_clean) + " of " + std::to_string(cosim_rows) +
          " `cosim` rows (ideal and realistic sensing)",
      options.quick ? "a --quick flight stops after 20 s, before the goal"
                    : "a grown plan flown smoothly still touched an obstacle or missed the goal "
                      "in a `cosim` row (see the table)"));
  findings.push_back(statedFinding(
      "The thesis's vehicle (Peter Corke's Simulink quadrotor) and start [3,3,2]",
      Finding::Verdict::kDiffers, "quad_1500g (PX4's Iris) from [3,2,2]",
      "the thesis gives no parameters for its model, and its planning tables start at [3,2,2]"));
  return findings;
}

}  // namespace

Report seed003Flight(const Options& options) {
  std::ostringstream md;
  std::vector<JsonObject> rows;
  md << flightIntroduction(options);
  int index = 0;
  FlightTally tally;
  for (const PathSetting& path : flightPaths())
    for (const Pipeline& p : flightPipelines())
      rows.push_back(flyOne(options, path, p, index++, md, tally));
  md << "\nEach flight's files (metrics.json, timeseries.csv, path.csv, final.png) are in the "
        "flight* folders beside this report.\n\n"
     << flightMap(options, tally.drawn);
  md << agreementSection(flightFindings(options, tally));
  return {md.str(), rows};
}

}  // namespace cosim::reproduce
