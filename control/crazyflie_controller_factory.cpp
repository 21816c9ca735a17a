#include "control/crazyflie_controller_factory.h"

#include <cmath>

#include "control/crazyflie_lee_controller.h"
#include "control/crazyflie_mellinger_controller.h"
#include "control/crazyflie_pid_controller.h"
#include "control/gain_reading.h"

namespace cosim {

namespace {

// controller.gains.mass (ctrlLee.mass, ctrlMel.mass), kg; absent: -1, the airframe's mass. A given
// mass is a real vehicle's: from 10 g (a third of the 27 g Crazyflie 2.1, the lightest model) to
// 100 kg. Zero or a negative value used to mean "the airframe's" silently, and 1e-300 was taken.
double readBelievedMass(ParamSet& p) {
  if (!p.has("mass")) return p.getDouble("mass", -1.0, -1.0, 100.0);
  return p.getDouble("mass", 0.0393, 0.01, 100.0);
}

// x and y share one gain; z has its own (the firmware's defaults are symmetric in x and y).
CrazyflieLeeGains readLee(ParamSet& p) {
  CrazyflieLeeGains g;
  g.kpos_p = readHorizontalAndZ(p, "kpos_p", g.kpos_p, 1e4);
  g.kpos_d = readHorizontalAndZ(p, "kpos_d", g.kpos_d, 1e4);
  g.kpos_i = readHorizontalAndZ(p, "kpos_i", g.kpos_i, 1e4);
  g.kpos_p_limit = p.getDouble("kpos_p_limit", g.kpos_p_limit, 0.0, 1e4);
  g.kpos_d_limit = p.getDouble("kpos_d_limit", g.kpos_d_limit, 0.0, 1e4);
  g.k_r = readHorizontalAndZ(p, "kr", g.k_r, 10.0);
  g.k_omega = readHorizontalAndZ(p, "komega", g.k_omega, 10.0);
  g.k_i = readHorizontalAndZ(p, "ki", g.k_i, 10.0);
  g.mass = readBelievedMass(p);
  return g;
}

CrazyflieMellingerGains readMellinger(ParamSet& p) {
  CrazyflieMellingerGains g;
  g.mass = readBelievedMass(p);
  g.mass_thrust = p.getDouble("mass_thrust", g.mass_thrust, 0.0, 1e7);
  g.kp_xy = p.getDouble("kp_xy", g.kp_xy, 0.0, 1e3);
  g.kd_xy = p.getDouble("kd_xy", g.kd_xy, 0.0, 1e3);
  g.ki_xy = p.getDouble("ki_xy", g.ki_xy, 0.0, 1e3);
  g.kp_z = p.getDouble("kp_z", g.kp_z, 0.0, 1e3);
  g.kd_z = p.getDouble("kd_z", g.kd_z, 0.0, 1e3);
  g.ki_z = p.getDouble("ki_z", g.ki_z, 0.0, 1e3);
  g.kR_xy = p.getDouble("kr_xy", g.kR_xy, 0.0, 1e7);
  g.kw_xy = p.getDouble("kw_xy", g.kw_xy, 0.0, 1e7);
  g.kR_z = p.getDouble("kr_z", g.kR_z, 0.0, 1e7);
  g.kw_z = p.getDouble("kw_z", g.kw_z, 0.0, 1e7);
  g.ki_m_z = p.getDouble("ki_m_z", g.ki_m_z, 0.0, 1e7);
  g.kd_omega_rp = p.getDouble("kd_omega_rp", g.kd_omega_rp, 0.0, 1e7);
  return g;
}

CrazyfliePidGains readPid(ParamSet& p) {
  CrazyfliePidGains g;
  g.pos_kp_xy = p.getDouble("pos_kp_xy", g.pos_kp_xy, 0.0, 1e3);
  g.pos_kp_z = p.getDouble("pos_kp_z", g.pos_kp_z, 0.0, 1e3);
  g.pos_ki_z = p.getDouble("pos_ki_z", g.pos_ki_z, 0.0, 1e3);
  g.vel_kp_xy = p.getDouble("vel_kp_xy", g.vel_kp_xy, 0.0, 1e3);
  g.vel_ki_xy = p.getDouble("vel_ki_xy", g.vel_ki_xy, 0.0, 1e3);
  g.vel_kp_z = p.getDouble("vel_kp_z", g.vel_kp_z, 0.0, 1e3);
  g.vel_ki_z = p.getDouble("vel_ki_z", g.vel_ki_z, 0.0, 1e3);
  g.vel_max = p.getDouble("vel_max", g.vel_max, 0.01, 100.0);
  g.rp_max_deg = p.getDouble("rp_max_deg", g.rp_max_deg, 1.0, 89.0);
  g.thrust_base = p.getDouble("thrust_base", g.thrust_base, 0.0, 65535.0);
  g.thrust_min = p.getDouble("thrust_min", g.thrust_min, 0.0, 65535.0);
  g.rate_kp_rp = p.getDouble("rate_kp_rp", g.rate_kp_rp, 0.0, 1e4);
  g.rate_ki_rp = p.getDouble("rate_ki_rp", g.rate_ki_rp, 0.0, 1e4);
  g.rate_kd_rp = p.getDouble("rate_kd_rp", g.rate_kd_rp, 0.0, 1e4);
  g.att_kp_rp = p.getDouble("att_kp_rp", g.att_kp_rp, 0.0, 1e3);
  g.att_ki_rp = p.getDouble("att_ki_rp", g.att_ki_rp, 0.0, 1e3);
  return g;
}

}  // namespace

std::unique_ptr<FlightController> makeCrazyflieController(const std::string& name, ParamSet& gains,
                                                          const QuadrotorParams& params,
                                                          const CrazyflieThrustPath& thrust_path) {
  std::unique_ptr<CrazyflieFirmwareController> c;
  if (name == "crazyflie_lee")
    c = std::make_unique<CrazyflieLeeController>(params, readLee(gains));
  else if (name == "crazyflie_mellinger")
    c = std::make_unique<CrazyflieMellingerController>(params, readMellinger(gains));
  else if (name == "crazyflie_pid")
    c = std::make_unique<CrazyfliePidController>(params, readPid(gains));
  else
    return nullptr;
  c->setThrustPath(thrust_path);
  return c;
}

}  // namespace cosim
