#include "sim/rotor_aerodynamics.h"

namespace cosim {

Wrench rotorDragWrench(const QuadrotorParams& p, const AirframeMotion& s,
                       const Eigen::Vector4d& w) {
  // Summed in the body frame, where the hubs and the rotor axis (z) are constants, and turned
  // into the world once: the same sums with three rotations instead of six (this runs at every
  // physics step).
  const Eigen::Vector3d v_body = s.R.transpose() * (s.velocity - s.wind);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r(p.rotor_xy[i].x(), p.rotor_xy[i].y(), p.rotor_z);
    const Eigen::Vector3d v_air = v_body + s.angular_velocity.cross(r);
    const Eigen::Vector3d v_perp(v_air.x(), v_air.y(), 0.0);  // less its part along the axis
    const Eigen::Vector3d drag = -w[i] * p.rotor_drag_coefficient * v_perp;
    force += drag;
    torque += r.cross(drag);
    // PX4's turning_direction is +1 for a counter-clockwise rotor; spin[i] (the reaction
    // torque's sign, models/quad_1500g.xml) is +1 for a clockwise one.
    const double ccw = -p.spin[i];
    torque += -w[i] * ccw * p.rolling_moment_coefficient * v_perp;
  }
  Wrench out;
  out.force = s.R * force;
  out.torque = s.R * torque;
  return out;
}

}  // namespace cosim
