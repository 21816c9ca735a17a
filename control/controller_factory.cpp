#include "control/controller_factory.h"

#include "control/cascade_controller.h"
#include "control/crazyflie_controller_factory.h"
#include "control/dsl_pid_controller.h"
#include "control/gain_reading.h"
#include "control/geometric_controller.h"
#include "control/indi_controller.h"
#include "core/input_error.h"

namespace cosim {

namespace {

// Roll and pitch share one gain (the airframe is symmetric); yaw has its own.
CascadeGains readCascadeGains(ParamSet& p) {
  CascadeGains g;
  g.pos_kp = p.getDouble("pos_kp", g.pos_kp, 0.0, 100.0);
  g.vel_kp = p.getDouble("vel_kp", g.vel_kp, 0.0, 100.0);
  g.vel_ki = p.getDouble("vel_ki", g.vel_ki, 0.0, 100.0);
  g.vel_i_limit = p.getDouble("vel_i_limit", g.vel_i_limit, 0.0, 100.0);
  g.max_speed_xy = p.getDouble("max_speed_xy", g.max_speed_xy, 0.01, 100.0);
  g.max_speed_z = p.getDouble("max_speed_z", g.max_speed_z, 0.01, 100.0);
  g.max_tilt_deg = p.getDouble("max_tilt_deg", g.max_tilt_deg, 1.0, 89.0);
  g.att_kp = readRollPitchAndYaw(p, "att_kp", g.att_kp, 1e4);
  g.rate_kp = readRollPitchAndYaw(p, "rate_kp", g.rate_kp, 1e4);
  g.rate_ki = readRollPitchAndYaw(p, "rate_ki", g.rate_ki, 1e4);
  g.max_rate = p.getDouble("max_rate", g.max_rate, 0.1, 100.0);
  return g;
}

GeometricGains readGeometricGains(ParamSet& p) {
  GeometricGains g;
  // Horizontal axes share one gain; z has its own.
  g.k_x = readHorizontalAndZ(p, "k_x", g.k_x, 1e4);
  g.k_v = readHorizontalAndZ(p, "k_v", g.k_v, 1e4);
  g.k_i = p.getDouble("k_i", g.k_i, 0.0, 1e4);
  g.i_limit = p.getDouble("i_limit", g.i_limit, 0.0, 100.0);
  g.i_velocity_zone = p.getDouble("i_velocity_zone", g.i_velocity_zone, 0.0, 100.0);
  g.k_R = readRollPitchAndYaw(p, "k_R", g.k_R, 1e4);
  g.k_omega = readRollPitchAndYaw(p, "k_omega", g.k_omega, 1e4);
  g.max_tilt_deg = p.getDouble("max_tilt_deg", g.max_tilt_deg, 1.0, 89.0);
  return g;
}

IndiGains readIndiGains(ParamSet& p) {
  IndiGains g;
  g.k_x = readHorizontalAndZ(p, "k_x", g.k_x, 1e4);
  g.k_v = readHorizontalAndZ(p, "k_v", g.k_v, 1e4);
  g.k_xi = readRollPitchAndYaw(p, "k_xi", g.k_xi, 1e4);
  g.k_omega = readRollPitchAndYaw(p, "k_omega", g.k_omega, 1e4);
  g.filter_cutoff_hz = p.getDouble("filter_cutoff_hz", g.filter_cutoff_hz, 0.1, 1e4);
  g.max_tilt_deg = p.getDouble("max_tilt_deg", g.max_tilt_deg, 1.0, 89.0);
  return g;
}

// In DSLPIDControl.py's own units (the CF2X's N and PWM; see control/dsl_pid_controller.h).
DslPidGains readDslPidGains(ParamSet& p) {
  DslPidGains g;
  g.p_for = readHorizontalAndZ(p, "p_for", g.p_for, 1e3);
  g.i_for = readHorizontalAndZ(p, "i_for", g.i_for, 1e3);
  g.d_for = readHorizontalAndZ(p, "d_for", g.d_for, 1e3);
  g.i_pos_limit_xy = p.getDouble("i_pos_limit_xy", g.i_pos_limit_xy, 0.0, 1e3);
  g.i_pos_limit_z = p.getDouble("i_pos_limit_z", g.i_pos_limit_z, 0.0, 1e3);
  g.p_tor = readRollPitchAndYaw(p, "p_tor", g.p_tor, 1e7);
  g.i_tor = readRollPitchAndYaw(p, "i_tor", g.i_tor, 1e7);
  g.d_tor = readRollPitchAndYaw(p, "d_tor", g.d_tor, 1e7);
  g.i_rpy_limit_rp = p.getDouble("i_rpy_limit_rp", g.i_rpy_limit_rp, 0.0, 1e4);
  g.i_rpy_limit_yaw = p.getDouble("i_rpy_limit_yaw", g.i_rpy_limit_yaw, 0.0, 1e4);
  g.max_torque_pwm = p.getDouble("max_torque_pwm", g.max_torque_pwm, 0.0, 65535.0);
  return g;
}

}  // namespace

std::unique_ptr<FlightController> makeFlightController(const std::string& name, ParamSet& gains,
                                                       const QuadrotorParams& params,
                                                       bool drag_compensation,
                                                       const CrazyflieThrustPath& thrust_path) {
  std::unique_ptr<FlightController> c;
  if (name == "cascade") {
    c = std::make_unique<CascadeController>(params, readCascadeGains(gains));
  } else if (name == "geometric") {
    c = std::make_unique<GeometricController>(params, readGeometricGains(gains), drag_compensation);
  } else if (name == "indi") {
    c = std::make_unique<IndiController>(params, readIndiGains(gains), drag_compensation);
  } else if (name == "dsl_pid") {
    c = std::make_unique<DslPidController>(params, readDslPidGains(gains));
  } else if (auto cf = makeCrazyflieController(name, gains, params, thrust_path)) {
    c = std::move(cf);
  } else {
    throw InputError(gains.file(), "key controller.name", "unknown controller '" + name + "'");
  }
  if (drag_compensation && name != "geometric" && name != "indi")
    throw InputError(gains.file(), "key controller.drag_compensation",
                     "drag_compensation applies to geometric and indi, not to '" + name + "'");
  gains.requireAllUsed("controller '" + name + "'");
  return c;
}

}  // namespace cosim
