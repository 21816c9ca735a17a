#pragma once
// A validated scenario: what a scenario YAML file says, checked. Everything downstream (the
// MuJoCo model, the planners' worlds, the controller, rendering) is built from this value.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/world/world.h"
#include "sim/airframe_file.h"
#include "sim/battery.h"
#include "sim/disturbance_settings.h"
#include "sim/model_error.h"
#include "sim/motion_sections.h"
#include "sim/render_settings.h"
#include "sim/sensors/sensor_settings.h"
#include "sim/sim_settings.h"
#include "sim/team_settings.h"
#include "sim/vehicle_kind.h"

namespace cosim {

class PiecewisePolynomialReference;  // control/piecewise_polynomial_reference.h

struct VehicleSpec {
  std::string name;   // unique; prefixes every MuJoCo name of the vehicle ("uav1/base")
  std::string model;  // a model name from models/ (cf2, quad_1500g, ...) or a URDF path
  std::filesystem::path model_file;           // resolved
  VehicleKind kind = VehicleKind::Quadrotor;  // a ground robot (URDF) plans in the plane, z = 0
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  // Points to visit after the start; the last one is the goal.
  std::vector<Eigen::Vector3d> waypoints;
  double yaw_deg = 0.0;  // initial and reference heading
  // The real total mass in kg (decks, battery, markers); 0: the model file's own. The physics
  // gets this mass and the model's inertia scaled by the same ratio (constant radii of
  // gyration); what a flight controller believes is its own business (docs/crazyflie.md).
  double mass = 0.0;
  // vehicles[i].airframe (sim/airframe_file.h): identified airframe parameters that replace the
  // model file's (empty file: none). Its motor_speed_coefficients [c0, c1, c2] are carried here
  // for a motor model driven by PWM and battery voltage.
  AirframeFile airframe;
  // vehicles[i].reference (sim/scenario_reference.h): a given reference flown instead of a
  // planned path, placed (its timescale, and the start added with `relative`); then `waypoints`
  // holds its last point alone, the goal. Null: the vehicle is planned.
  std::shared_ptr<const PiecewisePolynomialReference> reference;
  std::filesystem::path reference_file;  // resolved
  // The reference file's bytes as read: a run keeps a copy in its folder (runReferenceCopyName),
  // so the run renders again after the original moved. Null without a reference.
  std::shared_ptr<const std::string> reference_text;
  // vehicles[i].battery (sim/battery.h): the vehicle flies on a simulated battery, its
  // crazyflie_* controller driving the motors by duty cycle; empty: an ideal supply.
  std::optional<BatterySettings> battery;
  // vehicles[i].motor_speed_map: [c0, c1, c2] in place of the model file's
  // (QuadrotorParams::motor_speed_map).
  std::optional<Eigen::Vector3d> motor_speed_map;
  const Eigen::Vector3d& goal() const { return waypoints.back(); }
};

// An obstacle that moves: a cylinder or box standing on the floor whose centre travels
// along `path` (x, y in metres) at `speed` (m/s), back and forth (or round in a loop). In MuJoCo
// it is a mocap body driven every step; planners do not see it, navigators sense it.
struct MovingObstacleSpec {
  ObstacleType type = ObstacleType::Cylinder;      // Cylinder or Box
  double radius = 0.0;                             // cylinder, m
  double height = 1.0;                             // m
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // box: full edge lengths, m
  std::vector<Eigen::Vector2d> path;               // at least one point; one = standing still
  double speed = 0.0;                              // m/s
  bool loop = false;                               // false: back and forth; true: last -> first
};

// world.grid_map (seed 004's grid worlds): a MovingAI .map is the floor plan. Its blocked cells
// (plus `blocked`, cells the user adds) stand as boxes of `height` (planning/world/
// grid_map_world.h), the world spans the map from z = 0 to `ceiling`, and a team plan uses these
// very cells (cell (x, y), x = column, y = row, is [x c, (x+1) c) x [y c, (y+1) c)) instead of a
// grid voxelised from the boxes, which would block every free cell beside a block.
struct GridMapSpec {
  std::filesystem::path file;  // empty: the world has no grid map
  double cell = 0.5;           // m per cell
  double height = 0.5;         // m
  double ceiling = 3.0;        // m
  OccupancyGrid grid;          // the map (with the user's cells), cell size `cell`, origin 0
  bool present() const { return !file.empty(); }

  // The keys (sim/declared_keys.h); file and blocked are read by sim/scenario_world.cpp.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.custom("file", "path", "a MovingAI .map, relative to the scenario's folder; required");
    v.number("cell", cell, 0.01, 100.0, "m, a map cell's edge");
    v.number("height", height, 0.01, 100.0, "m, the blocked cells' boxes' height");
    v.number("ceiling", ceiling, 0.02, 1000.0, "m, the world's top, above `height`");
    v.custom("blocked", "[[x, y], ...]", "more blocked cells (column, row)");
  }
};

struct Scenario {
  std::string file;  // as given, for messages
  // Set for a run folder's scenario.yaml alone (parseRunFolderScenario): the folder, whose copy
  // of each vehicle's reference file (runReferenceCopyName) is read instead of the original.
  std::filesystem::path reference_copies_dir;
  std::string effective_yaml;  // the document after --set overrides (saved with each run)
  World world;
  GridMapSpec grid_map;                // world.grid_map; then world.bounds/obstacles come from it
  std::filesystem::path include_file;  // optional MJCF fragment with more geometry
  std::vector<MovingObstacleSpec> moving_obstacles;  // world.moving_obstacles
  std::vector<VehicleSpec> vehicles;

  // The top-level planner, trajectory and controller sections (sim/motion_sections.h).
  MotionSections motion;
  // The `aerial` ones: the quadrotors' when there are ground robots too (the top-level ones then
  // drive the robots).
  MotionSections aerial;

  SimSettings sim;
  TeamSettings team;  // a quadrotor team's plan verification and thrust limit
  DisturbanceSettings disturbances;
  SensorSettings sensors;       // what each quadrotor measures (default: ideal)
  EstimatorSettings estimator;  // what turns the measurements into the controller's state
  ModelError model_error;       // the flight software's belief against the simulated truth
  RenderSettings render;
};

// Reads and validates a scenario file. `overrides` are "key=value" strings (from --set) applied
// before validation. Throws InputError (file, line/key, problem) on any defect.
Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides = {});
// Same, from text (for tests and fuzzing); `file` is used in messages and to resolve relative
// paths.
Scenario parseScenario(const std::string& text, const std::string& file,
                       const std::vector<std::string>& overrides = {});

// A run folder's scenario.yaml: `text`, read from `file` (the file messages name, with its
// lines); relative paths resolve in `base_dir`, the folder of the scenario the run read, and
// each vehicle's reference is the copy the run kept in `run_dir` when there is one.
Scenario parseRunFolderScenario(const std::string& text, const std::string& file,
                                const std::filesystem::path& base_dir,
                                const std::filesystem::path& run_dir);

// "reference_<i>.csv": the file in which a run keeps vehicle i's reference file.
std::string runReferenceCopyName(std::size_t vehicle);

// Where the bundled models live (COSIM_MODELS_DIR env var, else the source tree's models/).
std::filesystem::path modelsDirectory();

// The file a vehicle's `model:` names: a path ending in .urdf (relative to the scenario's
// folder), else models/<model>.xml (a quadrotor) or models/<model>.urdf (a bundled ground
// robot). `kind` says which; the file may not exist.
std::filesystem::path resolveModelFile(const std::string& model,
                                       const std::filesystem::path& scenario_dir,
                                       VehicleKind& kind);

}  // namespace cosim
