#include "sim/rotor_aerodynamics.h"

namespace cosim {

Wrench rotorDragWrench(const QuadrotorParams& p, const AirframeMotion& s,
                       const Eigen::Vector4d& w) {
  Wrench out;
  const Eigen::Vector3d axis = s.R.col(2);
  const Eigen::Vector3d omega_world = s.R * s.angular_velocity;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d r =
        s.R * Eigen::Vector3d(p.rotor_xy[i].x(), p.rotor_xy[i].y(), p.rotor_z);
    const Eigen::Vector3d v_air = s.velocity + omega_world.cross(r) - s.wind;
    const Eigen::Vector3d v_perp = v_air - v_air.dot(axis) * axis;
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

}  // namespace cosim
