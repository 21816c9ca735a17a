#include "control/crazyflie_pid_controller.h"

#include <algorithm>
#include <cmath>

#include "control/controller_registry.h"
namespace cosim {

namespace {

double wrap180(double a) {
  return std::remainder(a, 360.0);
}

constexpr double kRadToDeg = 180.0 / M_PI;
constexpr double kVelMaxOverhead = 1.10;   // position_controller_pid.c velMaxOverhead
constexpr double kRpLimitOverhead = 1.10;  // rpLimitOverhead
constexpr double kThrustScale = 1000.0;    // thrustScale
constexpr double kFullScale = 65535.0;     // UINT16_MAX
constexpr double kInt16Max = 32767.0;      // saturateSignedInt16

// Roll, pitch, yaw (degrees) of R = Rz(yaw) Ry(pitch) Rx(roll), right-handed.
Eigen::Vector3d eulerDeg(const Eigen::Matrix3d& R) {
  return kRadToDeg * Eigen::Vector3d(std::atan2(R(2, 1), R(2, 2)),
                                     std::asin(std::clamp(-R(2, 0), -1.0, 1.0)),
                                     std::atan2(R(1, 0), R(0, 0)));
}

CrazyfliePid makePid(double kp, double ki, double kd, double i_limit, double output_limit) {
  CrazyfliePid p;
  p.kp = kp;
  p.ki = ki;
  p.kd = kd;
  p.i_limit = i_limit;
  p.output_limit = output_limit;
  return p;
}

}  // namespace

double CrazyfliePid::update(double desired, double measured, double dt, bool wrap_deg) {
  double error = desired - measured;
  double delta = -(measured - prev_measured);
  if (wrap_deg) {
    error = wrap180(error);
    delta = wrap180(delta);
  }
  prev_measured = measured;
  integ += error * dt;
  if (i_limit != 0.0) integ = std::clamp(integ, -i_limit, i_limit);
  double out = kp * error + kd * delta / dt + ki * integ;
  if (output_limit != 0.0) out = std::clamp(out, -output_limit, output_limit);
  return out;
}

CrazyfliePidController::CrazyfliePidController(const QuadrotorParams& airframe,
                                               const CrazyfliePidGains& g,
                                               const CrazyfliePlatform& platform)
    : CrazyflieFirmwareController(airframe, platform), gains_(g) {
  const double vel_limit = g.vel_max * kVelMaxOverhead;
  pid_x_ = makePid(g.pos_kp_xy, g.pos_ki_xy, 0.0, 5000.0, vel_limit);
  pid_y_ = pid_x_;
  pid_z_ = makePid(g.pos_kp_z, g.pos_ki_z, 0.0, 5000.0, std::max(g.vel_max, 0.5) * kVelMaxOverhead);
  pid_vx_ = makePid(g.vel_kp_xy, g.vel_ki_xy, 0.0, 5000.0, g.rp_max_deg * kRpLimitOverhead);
  pid_vy_ = pid_vx_;
  pid_vz_ = makePid(g.vel_kp_z, g.vel_ki_z, 0.0, 5000.0, kFullScale / 2.0 / kThrustScale);
  pid_roll_ = makePid(g.att_kp_rp, g.att_ki_rp, 0.0, g.att_i_limit_rp, 0.0);
  pid_pitch_ = pid_roll_;
  pid_yaw_ = makePid(g.att_kp_yaw, g.att_ki_yaw, g.att_kd_yaw, g.att_i_limit_yaw, 0.0);
  pid_roll_rate_ = makePid(g.rate_kp_rp, g.rate_ki_rp, g.rate_kd_rp, g.rate_i_limit_rp, 0.0);
  pid_pitch_rate_ = pid_roll_rate_;
  pid_yaw_rate_ = makePid(g.rate_kp_yaw, g.rate_ki_yaw, 0.0, g.rate_i_limit_yaw, 0.0);
}

void CrazyfliePidController::resetLaw() {
  initialised_ = false;
  pos_ = PositionOutput{};
  att_out_.setZero();
}

void CrazyfliePidController::positionStep(const VehicleState& s, const FlatReference& sp,
                                          double yaw_deg) {
  const double dt = 1.0 / kCrazyfliePositionRate;
  const double c = std::cos(yaw_deg / kRadToDeg), sn = std::sin(yaw_deg / kRadToDeg);
  const auto body = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(v.x() * c + v.y() * sn, -v.x() * sn + v.y() * c, v.z());
  };
  const Eigen::Vector3d sp_b = body(sp.position), x_b = body(s.position), v_b = body(s.velocity);
  // Position -> velocity set-point (the reference velocity is not added: position mode).
  pos_.velocity_setpoint = {pid_x_.update(sp_b.x(), x_b.x(), dt),
                            pid_y_.update(sp_b.y(), x_b.y(), dt),
                            pid_z_.update(sp_b.z(), x_b.z(), dt)};
  // Velocity -> tilt (right-handed: +pitch tilts the thrust towards +x, +roll towards -y).
  const double rp_max = gains_.rp_max_deg;
  pos_.pitch_deg =
      std::clamp(pid_vx_.update(pos_.velocity_setpoint.x(), v_b.x(), dt), -rp_max, rp_max);
  pos_.roll_deg =
      std::clamp(-pid_vy_.update(pos_.velocity_setpoint.y(), v_b.y(), dt), -rp_max, rp_max);
  const double raw = pid_vz_.update(pos_.velocity_setpoint.z(), v_b.z(), dt);
  pos_.thrust = std::clamp(std::max(raw * kThrustScale + gains_.thrust_base, gains_.thrust_min),
                           0.0, kFullScale);
}

void CrazyfliePidController::attitudeStep(const VehicleState& s, const Eigen::Vector3d& rpy,
                                          double yaw_sp_deg) {
  const double dt = 1.0 / kCrazyflieAttitudeRate;
  const Eigen::Vector3d rate_d(pid_roll_.update(pos_.roll_deg, rpy.x(), dt),
                               pid_pitch_.update(pos_.pitch_deg, rpy.y(), dt),
                               pid_yaw_.update(yaw_sp_deg, rpy.z(), dt, true));
  const Eigen::Vector3d gyro = kRadToDeg * s.angular_velocity;
  att_out_ = Eigen::Vector3d(pid_roll_rate_.update(rate_d.x(), gyro.x(), dt),
                             pid_pitch_rate_.update(rate_d.y(), gyro.y(), dt),
                             pid_yaw_rate_.update(rate_d.z(), gyro.z(), dt))
                 .cwiseMax(-kInt16Max)
                 .cwiseMin(kInt16Max);
}

Eigen::Vector4d CrazyfliePidController::lawStep(const VehicleState& s, const FlatReference& sp,
                                                const CrazyflieClock& clock) {
  const Eigen::Vector3d rpy = eulerDeg(s.attitude.toRotationMatrix());
  if (!initialised_) {  // controllerPidReinitialize on the first set-point: no bump
    for (CrazyfliePid* p : {&pid_x_, &pid_y_, &pid_z_}) p->reset(0.0);
    pid_x_.prev_measured = s.position.x();
    pid_y_.prev_measured = s.position.y();
    pid_z_.prev_measured = s.position.z();
    for (CrazyfliePid* p :
         {&pid_vx_, &pid_vy_, &pid_vz_, &pid_roll_rate_, &pid_pitch_rate_, &pid_yaw_rate_})
      p->reset(0.0);
    pid_roll_.reset(rpy.x());
    pid_pitch_.reset(rpy.y());
    pid_yaw_.reset(rpy.z());
    initialised_ = true;
  }
  const double yaw_sp_deg = wrap180(kRadToDeg * sp.yaw);
  if (clock.due(kCrazyfliePositionRate)) positionStep(s, sp, rpy.z());
  attitudeStep(s, rpy, yaw_sp_deg);
  if (pos_.thrust == 0.0) return Eigen::Vector4d::Zero();
  // Legacy signs: pitch positive nose up (-right-handed), yaw command -(right-handed yaw).
  return crazyflieLegacyMix(platform_, pos_.thrust, att_out_.x(), -att_out_.y(), -att_out_.z());
}

namespace {

const GainTable<CrazyfliePidGains>& crazyfliePidGains() {
  using G = CrazyfliePidGains;
  static const GainTable<G> table =
      GainTable<G>()
          .gain("pos_kp_xy", &G::pos_kp_xy, 0.0, 1e3, "PID_POS_X_KP (and Y): 1/s")
          .gain("pos_kp_z", &G::pos_kp_z, 0.0, 1e3, "PID_POS_Z_KP: 1/s")
          .gain("pos_ki_z", &G::pos_ki_z, 0.0, 1e3, "PID_POS_Z_KI: 1/s^2")
          .gain("vel_kp_xy", &G::vel_kp_xy, 0.0, 1e3, "PID_VEL_X_KP (and Y): deg per m/s")
          .gain("vel_ki_xy", &G::vel_ki_xy, 0.0, 1e3, "PID_VEL_X_KI (and Y): deg per m")
          .gain("vel_kp_z", &G::vel_kp_z, 0.0, 1e3, "PID_VEL_Z_KP: thrust/1000 per m/s")
          .gain("vel_ki_z", &G::vel_ki_z, 0.0, 1e3, "PID_VEL_Z_KI: thrust/1000 per m")
          .gain("vel_max", &G::vel_max, 0.01, 100.0,
                "PID_POS_VEL_X/Y/Z_MAX: velocity set-point limit (x 1.10 overhead), m/s")
          .gain("rp_max_deg", &G::rp_max_deg, 1.0, 89.0,
                "PID_VEL_ROLL_MAX, PID_VEL_PITCH_MAX: tilt limit, deg")
          .gain("thrust_base", &G::thrust_base, 0.0, 65535.0,
                "PID_VEL_THRUST_BASE: hover thrust, 16-bit scale")
          .gain("thrust_min", &G::thrust_min, 0.0, 65535.0,
                "PID_VEL_THRUST_MIN: least thrust, 16-bit scale")
          .gain("rate_kp_rp", &G::rate_kp_rp, 0.0, 1e4, "PID_ROLL_RATE_KP (and pitch)")
          .gain("rate_ki_rp", &G::rate_ki_rp, 0.0, 1e4, "PID_ROLL_RATE_KI (and pitch)")
          .gain("rate_kd_rp", &G::rate_kd_rp, 0.0, 1e4, "PID_ROLL_RATE_KD (and pitch)")
          .gain("att_kp_rp", &G::att_kp_rp, 0.0, 1e3, "PID_ROLL_KP (and pitch): deg/s per deg")
          .gain("att_ki_rp", &G::att_ki_rp, 0.0, 1e3, "PID_ROLL_KI (and pitch): deg/s per deg s");
  return table;
}

}  // namespace

void registerCrazyfliePidController(ControllerRegistry& registry) {
  ControllerEntry e;
  e.name = CrazyfliePidController::kName;
  e.summary =
      "crazyflie-firmware's cascaded PID (controller_pid.c), 100 Hz position, 500 Hz attitude";
  e.gains = crazyfliePidGains().declarations();
  e.team_shortfall = 0.50;  // swarm32 1.00 (and a pillar hit), dense 1.41
  e.crazyflie_thrust_path = true;
  e.make = [](const QuadrotorParams& params, ParamSet& gains,
              const ControllerOptions& options) -> std::unique_ptr<FlightController> {
    auto c = std::make_unique<CrazyfliePidController>(params, crazyfliePidGains().read(gains));
    c->setThrustPath(options.thrust_path);
    return c;
  };
  registry.add(std::move(e));
}

}  // namespace cosim
