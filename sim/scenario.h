#pragma once
// A validated scenario: what a scenario YAML file says, checked. Everything downstream (the
// MuJoCo model, the planners' worlds, the controller, rendering) is built from this value.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "control/crazyflie_thrust_path.h"
#include "core/param_set.h"
#include "planning/grid/occupancy_grid.h"
#include "planning/team/separation_ellipsoid.h"
#include "planning/world/world.h"
#include "sim/airframe_file.h"
#include "sim/battery.h"
#include "sim/camera_kind.h"
#include "sim/disturbance_settings.h"
#include "sim/model_error.h"
#include "sim/sensors/sensor_settings.h"
#include "sim/trajectory_mode.h"
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
};

struct SimSettings {
  double timestep = 0.001;    // s, physics step
  double control_rate = 500;  // Hz, controller rate; the physics rate must be a multiple
  double max_time = 120.0;    // s of simulated time before giving up
  std::uint64_t seed = 1;
  double goal_tolerance = 0.2;  // m: the goal is reached within this distance (seed 003: 0.2 m)
};

// The cameras: sim/camera_kind.h (fixed looks from fixed_pos at fixed_lookat).
struct RenderSettings {
  CameraKind camera = CameraKind::Chase;  // the main video, video.mp4
  std::vector<CameraKind> cameras;        // more videos, one per camera: video_<camera>.mp4
  int width = 1280, height = 720, fps = 30;
  double speedup = 1.0;           // simulated seconds per second of video
  bool has_fixed_camera = false;  // render.fixed_camera: {pos: [x,y,z], lookat: [x,y,z]}
  Eigen::Vector3d fixed_pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d fixed_lookat = Eigen::Vector3d::Zero();
  double obstacle_alpha = 1.0;  // below 1: obstacles are see-through
  bool png_frames = false;      // also write each video as frames_<camera>/NNNNN.png
  // A team's pictures draw every member's planned path and reference too (off: the flown paths
  // only; a grid plan's right angles, one per member, tangle a team's picture).
  bool team_plans = false;
};

// The quadrotors' planner, trajectory and controller in a scenario that also has ground robots
// (the `aerial` section; the top-level sections then drive the robots). Same keys and meaning as
// the top-level planner, trajectory and controller sections.
struct AerialSections {
  std::string planner_name;  // empty: fly the given waypoints
  ParamSet planner_params;
  double planner_margin = 0.3;
  std::optional<SeparationEllipsoid> planner_separation;
  TrajectoryMode trajectory_mode = TrajectoryMode::Waypoints;
  ParamSet trajectory_params;
  std::string controller_name = "cascade";
  bool controller_given = false;  // a controller section was written
  bool controller_drag_compensation = false;
  ParamSet controller_gains;
  CrazyflieThrustPath controller_thrust_path;
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

  // Planner: empty name = fly the vehicle's waypoints as given.
  std::string planner_name;
  ParamSet planner_params;      // everything under planner: except name and margin
  double planner_margin = 0.3;  // m, safety margin added to the vehicle radius
  // planner.separation of a quadrotor team; absent: each model's own (its model file).
  std::optional<SeparationEllipsoid> planner_separation;

  TrajectoryMode trajectory_mode = TrajectoryMode::Waypoints;
  ParamSet trajectory_params;  // max_speed, switch_radius, ...

  std::string controller_name = "cascade";  // cascade | geometric | indi | dsl_pid | crazyflie_*
  // A controller section was written; without one a quadrotor team flies indi (run_pipeline.cpp).
  bool controller_given = false;
  // controller.drag_compensation: rotor drag in the flatness feed-forward (geometric, indi).
  bool controller_drag_compensation = false;
  ParamSet controller_gains;
  // controller.thrust_map, thrust_map_coefficients, idle_thrust, platform (crazyflie_* only).
  CrazyflieThrustPath controller_thrust_path;

  AerialSections aerial;  // for the quadrotors when there are ground robots too

  SimSettings sim;
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
