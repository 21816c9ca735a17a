#pragma once
// What a simulation run records, sample by sample at the control rate. Metrics and rendering
// are both computed from this log, never from the live simulation, so a run can be re-rendered
// or re-evaluated without simulating it again.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace cosim {

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
  // "goal", "max_time", "interrupted", "diverged" (NaN or runaway state), "unstable" (MuJoCo
  // bad-number warning), "saturated" (mixer saturated for more than 2 s on end)
  std::string end_reason;
  int mujoco_warnings = 0;
};

}  // namespace cosim
