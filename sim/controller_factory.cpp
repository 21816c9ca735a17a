#include "sim/controller_factory.h"

#include "control/cascade_controller.h"
#include "control/geometric_controller.h"
#include "planning/input_error.h"

namespace cosim {

namespace {

Eigen::Vector3d readAxes(ParamSet& p, const std::string& prefix, const Eigen::Vector3d& fallback) {
  // Roll and pitch share one gain (the airframe is symmetric); yaw has its own.
  const double rp = p.getDouble(prefix + "_rp", fallback.x(), 0.0, 1e4);
  const double yaw = p.getDouble(prefix + "_yaw", fallback.z(), 0.0, 1e4);
  return {rp, rp, yaw};
}

CascadeGains readCascadeGains(ParamSet& p) {
  CascadeGains g;
  g.pos_kp = p.getDouble("pos_kp", g.pos_kp, 0.0, 100.0);
  g.vel_kp = p.getDouble("vel_kp", g.vel_kp, 0.0, 100.0);
  g.vel_ki = p.getDouble("vel_ki", g.vel_ki, 0.0, 100.0);
  g.vel_i_limit = p.getDouble("vel_i_limit", g.vel_i_limit, 0.0, 100.0);
  g.max_speed_xy = p.getDouble("max_speed_xy", g.max_speed_xy, 0.01, 100.0);
  g.max_speed_z = p.getDouble("max_speed_z", g.max_speed_z, 0.01, 100.0);
  g.max_tilt_deg = p.getDouble("max_tilt_deg", g.max_tilt_deg, 1.0, 89.0);
  g.att_kp = readAxes(p, "att_kp", g.att_kp);
  g.rate_kp = readAxes(p, "rate_kp", g.rate_kp);
  g.rate_ki = readAxes(p, "rate_ki", g.rate_ki);
  g.max_rate = p.getDouble("max_rate", g.max_rate, 0.1, 100.0);
  return g;
}

GeometricGains readGeometricGains(ParamSet& p) {
  GeometricGains g;
  // Horizontal axes share one gain; z has its own.
  const double kx_xy = p.getDouble("k_x_xy", g.k_x.x(), 0.0, 1e4);
  g.k_x = {kx_xy, kx_xy, p.getDouble("k_x_z", g.k_x.z(), 0.0, 1e4)};
  const double kv_xy = p.getDouble("k_v_xy", g.k_v.x(), 0.0, 1e4);
  g.k_v = {kv_xy, kv_xy, p.getDouble("k_v_z", g.k_v.z(), 0.0, 1e4)};
  g.k_i = p.getDouble("k_i", g.k_i, 0.0, 1e4);
  g.i_limit = p.getDouble("i_limit", g.i_limit, 0.0, 100.0);
  g.i_velocity_zone = p.getDouble("i_velocity_zone", g.i_velocity_zone, 0.0, 100.0);
  g.k_R = readAxes(p, "k_R", g.k_R);
  g.k_omega = readAxes(p, "k_omega", g.k_omega);
  g.max_tilt_deg = p.getDouble("max_tilt_deg", g.max_tilt_deg, 1.0, 89.0);
  return g;
}

}  // namespace

std::unique_ptr<FlightController> makeFlightController(const std::string& name, ParamSet& gains,
                                                       const QuadrotorParams& params) {
  std::unique_ptr<FlightController> c;
  if (name == "cascade") {
    c = std::make_unique<CascadeController>(params, readCascadeGains(gains));
  } else if (name == "geometric") {
    c = std::make_unique<GeometricController>(params, readGeometricGains(gains));
  } else {
    throw InputError(gains.file(), "key controller.name", "unknown controller '" + name + "'");
  }
  gains.requireAllUsed("controller '" + name + "'");
  return c;
}

}  // namespace cosim
