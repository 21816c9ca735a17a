#pragma once
// What every flight controller sees and returns: the measured state and a flat-output reference
// in, rotor thrusts out. Controllers know nothing of MuJoCo; sim/ calls them at their own rate.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

namespace cosim {

// What the controller knows of the vehicle: the estimator's output (sim/ with `sensors` and
// `estimator`), or the exact state with ideal sensing.
struct VehicleState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();            // world, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // world, m/s
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // body to world
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();    // body frame, rad/s (gyro - bias)
  // The accelerometer's reading less its estimated bias: specific force (acceleration minus
  // gravity) in the body frame, m/s^2; (0, 0, g) in hover. Incremental controllers (INDI) feed
  // back on it.
  Eigen::Vector3d specific_force = Eigen::Vector3d::Zero();
  // Each rotor's thrust as the controller can know it: the measured rotor speed (ESC telemetry,
  // or the optical encoders of Tal and Karaman 2021) through the controller's own thrust
  // coefficient, k_f w^2, N. Same order as ControlOutput::rotor_thrusts.
  Eigen::Vector4d rotor_thrusts = Eigen::Vector4d::Zero();
  // The battery's voltage as the flight software measures it (crazyflie-firmware's pm.vbat), V;
  // 0: the vehicle carries no simulated battery (its supply is ideal).
  double battery_voltage = 0.0;
};

// The reference in the flat outputs (position and yaw) with derivatives for feed-forward.
struct FlatReference {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d jerk = Eigen::Vector3d::Zero();
  Eigen::Vector3d snap = Eigen::Vector3d::Zero();
  double yaw = 0.0;               // rad
  double yaw_rate = 0.0;          // rad/s
  double yaw_acceleration = 0.0;  // rad/s^2
};

struct ControlOutput {
  Eigen::Vector4d rotor_thrusts = Eigen::Vector4d::Zero();  // N, per rotor
  double collective_thrust = 0.0;                           // N, requested
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();         // N m, requested, body frame
  bool saturated = false;                                   // the mixer had to give something up
  // Flight software that drives its motors by PWM on a battery (the crazyflie_* controllers on a
  // vehicle with one): each rotor's duty cycle (0..1, same order as rotor_thrusts), which the
  // simulated motor turns into rotor speed on the battery's voltage (sim/quadrotor_plant.h);
  // rotor_thrusts is then what the controller asked for, not what the rotors make.
  Eigen::Vector4d motor_duty = Eigen::Vector4d::Zero();
  bool drives_duty = false;
};

class FlightController {
 public:
  virtual ~FlightController() = default;
  virtual std::string name() const = 0;
  virtual void reset() = 0;
  // dt: time since the previous call (the control period).
  virtual ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) = 0;
};

}  // namespace cosim
