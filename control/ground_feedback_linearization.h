#pragma once
// Trajectory tracking for a differential drive by input-output feedback linearisation
// (Siciliano, Sciavicco, Villani, Oriolo, "Robotics: Modelling, Planning and Control", Springer
// 2009, §11.6.2): a point B at distance b ahead of the axle has the fully actuated kinematics
//   d/dt p_B = [cos th, -b sin th; sin th, b cos th] [v; w],
// so the robot tracks a timed path with B driven by u = d/dt p_B,ref + k (p_B,ref - p_B) and
//   v = cos th u_x + sin th u_y,   w = (-sin th u_x + cos th u_y) / b.
// The reference for B is the robot's reference point shifted b along the reference's direction of
// motion (along the robot's heading while the reference rests), so at rest the axle centre
// settles on the reference point itself. Speed, yaw-rate and wheel-speed limits scale (v, w)
// together (the path's curvature is kept); then (v, w) are rate-limited.
#include "control/ground_controller.h"

namespace cosim {

struct GroundFeedbackLinearizationParams {
  double b = 0.08;  // m, the tracked point ahead of the axle (about half the robot's length)
  double k = 2.0;   // 1/s, error decay rate of the tracked point
  double wheel_separation = 0.16;  // m, for the wheel-speed limit |v| + |w| s / 2 <= max_speed
};

class GroundFeedbackLinearization : public GroundController {
 public:
  GroundFeedbackLinearization(GroundMotionLimits limits,
                              GroundFeedbackLinearizationParams params = {});
  void reset() override;
  GroundCommand update(const PlanarState& state, const PlanarReference& reference,
                       double dt) override;

 private:
  GroundMotionLimits limits_;
  GroundFeedbackLinearizationParams p_;
  double v_ = 0.0, w_ = 0.0;  // last command
};

}  // namespace cosim
