#pragma once
// What a simulation run records, sample by sample at the control rate. Metrics and rendering
// are both computed from this log, never from the live simulation, so a run can be re-rendered
// or re-evaluated without simulating it again.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cosim {

// How a run's simulation ended. Decisions use the enum; its name (runEndName) is written only
// where the end is shown: metrics.json's and run.json's end_reason, and messages.
enum class RunEnd {
  Running,      // not ended yet: a loop stepped from outside, looked at mid-run ("running")
  Goal,         // every vehicle reached its goal and held it ("goal")
  MaxTime,      // sim.max_time ran out ("max_time")
  Interrupted,  // SIGINT/SIGTERM, the run's interrupt flag ("interrupted")
  Diverged,     // NaN or runaway state ("diverged")
  Unstable,     // MuJoCo found bad numbers in the state or controls ("unstable")
  Saturated,    // a quadrotor's mixer stayed saturated too long ("saturated")
  GaveUp,       // the navigator gave up ("gave_up")
  NoPath,       // not simulated: a vehicle had no plan to follow ("no_path")
};

// The name a run's end is written with: "running", "goal", "max_time", ...
const char* runEndName(RunEnd end);
// The end written as `name` (run.json read back), or none for a name this version does not know.
std::optional<RunEnd> runEndNamed(std::string_view name);

struct LogSample {
  double t = 0.0;
  Eigen::Vector3d ref_pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d ref_vel = Eigen::Vector3d::Zero();
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d vel = Eigen::Vector3d::Zero();
  Eigen::Quaterniond att = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();         // body rates, rad/s
  // What the controller saw (the estimate; the truth above with ideal sensing).
  Eigen::Vector3d est_pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d est_vel = Eigen::Vector3d::Zero();
  Eigen::Quaterniond est_att = Eigen::Quaterniond::Identity();
  Eigen::Vector4d rotor_cmd = Eigen::Vector4d::Zero();     // commanded thrusts, N
  Eigen::Vector4d rotor_thrust = Eigen::Vector4d::Zero();  // actual (rotor lag, air effects), N
  Eigen::Vector4d rotor_speed = Eigen::Vector4d::Zero();   // rad/s
  bool saturated = false;
};

struct ContactEvent {
  double t = 0.0;
  std::string other;  // name of the geom hit
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
};

struct VehicleLog {
  std::string name;
  double radius = 0.0;     // bounding radius used for clearance
  double max_thrust = 0.0; // per rotor, N
  std::vector<Eigen::Vector3d> planned_path;  // what the planner produced
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  std::vector<LogSample> samples;
  std::vector<ContactEvent> collisions;  // onsets of contact with anything but the landing spot
  bool reached_goal = false;
  double arrival_time = -1.0;  // s, when the goal was reached
  // s: when the vehicle's given reference ends (its duration as flown, from t = 0); its tracking
  // error covers the samples up to then. Negative: no given reference (sim/flight_metrics.h).
  double reference_end = -1.0;
};

// A moving obstacle's centre over time (sampled with the vehicles), for metrics and rendering.
struct MovingObstacleLog {
  std::string name;  // its MuJoCo body ("moving<i>")
  double radius = 0.0;  // footprint radius, m
  std::vector<double> t;
  std::vector<Eigen::Vector3d> pos;
};

struct RunLog {
  std::vector<VehicleLog> vehicles;
  std::vector<MovingObstacleLog> moving_obstacles;
  double sim_time = 0.0;    // simulated seconds
  double wall_time = 0.0;   // wall-clock seconds of the simulation loop
  long physics_steps = 0;
  RunEnd end_reason = RunEnd::Running;
  int mujoco_warnings = 0;
};

}  // namespace cosim
