#pragma once
// A quadrotor's four rotors as the physics sees them: each rotor's speed w (rad/s) is a state
// that follows its commanded speed through a first-order lag whose time constant is tau_up while
// the rotor speeds up and tau_down while it slows down (the motor model of RotorS and PX4's
// Gazebo plugin, gazebo_motor_model.cpp: FirstOrderFilter with timeConstantUp/Down), and the
// rotor makes thrust T = k_f w^2 along its axis with a reaction torque (k_m / k_f) T about it
// (the actuator's gear). Speeds and commands are clamped to [w_min, w_max]. A command reaches
// the lag motor_delay seconds after it is given (a pure delay: the ESC's processing and PWM
// period, identified by cosim identify; 0, the default, applies each command at once).
//
// Why not MuJoCo's own actuator dynamics: MuJoCo 2.2.2's dyntype "filter" has one time constant,
// and a "user" dyntype goes through a process-wide callback (mjcb_act_dyn) shared by every model
// in the process. So the rotors are integrated here, exactly over each physics step, and the
// thrust is handed to MuJoCo as the actuator's control.
#include <Eigen/Core>
#include <deque>

#include "control/quadrotor_params.h"

namespace cosim {

class RotorModel {
 public:
  explicit RotorModel(const QuadrotorParams& airframe);

  // The speeds the motors are driven towards, rad/s (clamped).
  void command(const Eigen::Vector4d& speeds);
  // Spins every rotor at `speeds` at once (and commands them, dropping any delayed command),
  // e.g. already hovering at start.
  void reset(const Eigen::Vector4d& speeds);
  // Advances each speed by dt: w += (w_cmd - w) (1 - exp(-dt / tau)), tau = tau_up when
  // w_cmd > w, else tau_down (exact for a command held over dt). With a delay, w_cmd is the
  // latest command given at least motor_delay before the step's start.
  void advance(double dt);

  const Eigen::Vector4d& speeds() const { return speeds_; }
  // The command the lag follows now (with a delay, one given motor_delay ago).
  const Eigen::Vector4d& commands() const { return commands_; }
  // k_f w^2 per rotor, N.
  Eigen::Vector4d thrusts() const;

 private:
  Eigen::Vector4d clamped(const Eigen::Vector4d& w) const;

  struct DelayedCommand {
    double due;  // on the model's clock, s
    Eigen::Vector4d speeds;
  };
  double k_f_, w_min_, w_max_, tau_up_, tau_down_, delay_;
  double clock_ = 0.0;  // the time advanced so far, s
  std::deque<DelayedCommand> pending_;
  double cached_dt_ = -1.0, gain_up_ = 0.0, gain_down_ = 0.0;
  Eigen::Vector4d speeds_ = Eigen::Vector4d::Zero();
  Eigen::Vector4d commands_ = Eigen::Vector4d::Zero();
};

}  // namespace cosim
