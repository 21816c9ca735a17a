#include "sim/rotor_aerodynamics.h"

namespace cosim {

Wrench rotorDragWrenchBody(const QuadrotorParams& p, const AirframeMotion& s,
                           const Eigen::Vector4d& w) {
  // Summed in the body frame, where the hubs and the rotor axis (z) are constants: one rotation
  // for the air velocity instead of one per rotor (this runs at every physics step).
  const Eigen::Vector3d v_body = s.R.transpose() * (s.velocity - s.wind);
  Wrench out;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r(p.rotor_xy[i].x(), p.rotor_xy[i].y(), p.rotor_z);
    const Eigen::Vector3d v_air = v_body + s.angular_velocity.cross(r);
    const Eigen::Vector3d v_perp(v_air.x(), v_air.y(), 0.0);  // less its part along the axis
    const Eigen::Vector3d drag = -w[i] * p.rotor_drag_coefficient * v_perp;
    out.force += drag;
    out.torque += r.cross(drag);
    // PX4's turning_direction is +1 for a counter-clockwise rotor; spin[i] (the reaction
    // torque's sign, models/quad_1500g.xml) is +1 for a clockwise one.
    const double ccw = -p.spin[i];
    out.torque += -w[i] * ccw * p.rolling_moment_coefficient * v_perp;
  }
  return out;
}

Wrench rotorDragWrench(const QuadrotorParams& p, const AirframeMotion& s,
                       const Eigen::Vector4d& w) {
  Wrench out = rotorDragWrenchBody(p, s, w);
  out.force = s.R * out.force;
  out.torque = s.R * out.torque;
  return out;
}

}  // namespace cosim
