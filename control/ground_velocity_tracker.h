#pragma once
// Velocity tracking for a holonomic base: the commanded world velocity is the reference's
// velocity plus proportional feedback on the position error, v = v_ref + k_p (p_ref - p), and
// the heading follows the reference yaw, w = k_yaw (psi_ref - psi); both are cut to the speed
// limits and rate-limited to the acceleration limits, then turned into the body frame.
#include "control/ground_controller.h"

namespace cosim {

struct GroundVelocityTrackerGains {
  double k_position = 2.0;  // 1/s: position errors decay with a 0.5 s time constant
  double k_yaw = 3.0;       // 1/s
};

class GroundVelocityTracker : public GroundController {
 public:
  GroundVelocityTracker(GroundMotionLimits limits, GroundVelocityTrackerGains gains = {});
  void reset() override;
  GroundCommand update(const PlanarState& state, const PlanarReference& reference,
                       double dt) override;

 private:
  GroundMotionLimits limits_;
  GroundVelocityTrackerGains gains_;
  Eigen::Vector2d velocity_ = Eigen::Vector2d::Zero();  // last command, world frame
  double yaw_rate_ = 0.0;
};

}  // namespace cosim
