#pragma once
// The interface of ground-robot controllers: plain planar state and reference in, a body-frame
// velocity command out (the robot's motor drivers are velocity servos). No MuJoCo here.
#include <Eigen/Core>

namespace cosim {

struct PlanarState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // m, world frame
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // m/s, world frame
  double yaw = 0.0;                                    // rad
  double yaw_rate = 0.0;                               // rad/s
};

struct PlanarReference {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // feed-forward
  double yaw = 0.0;    // heading to hold (holonomic bases; differential drives ignore it)
  bool final = false;  // the reference has come to rest at its last point
};

// Body-frame twist: forward (x), lateral (y, zero for a differential drive), yaw rate.
struct GroundCommand {
  double forward = 0.0, lateral = 0.0, yaw_rate = 0.0;
  bool saturated = false;  // a speed or acceleration limit cut the command
};

// Limits on the commanded motion (what the drive can do and what the payload tolerates).
struct GroundMotionLimits {
  double max_speed = 0.5;             // m/s
  double max_acceleration = 1.0;      // m/s^2
  double max_yaw_rate = 2.0;          // rad/s
  double max_yaw_acceleration = 4.0;  // rad/s^2
  void validate() const;              // throws std::invalid_argument unless all positive
};

class GroundController {
 public:
  virtual ~GroundController() = default;
  virtual void reset() = 0;
  virtual GroundCommand update(const PlanarState& state, const PlanarReference& reference,
                               double dt) = 0;
};

// Wraps an angle to (-pi, pi].
double wrapAngle(double a);

// Moves `current` towards `target` by at most max_step in norm (a rate limit); true if it cut.
bool stepTowards(Eigen::Vector2d& current, const Eigen::Vector2d& target, double max_step);
bool stepTowards(double& current, double target, double max_step);

}  // namespace cosim
