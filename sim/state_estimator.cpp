#include "sim/state_estimator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "estimation/crazyflie_kalman_estimator.h"
#include "estimation/latency_compensated_ekf.h"

namespace cosim {

namespace {

// The estimator's starting uncertainty (1 sigma per axis), from what is known at take-off.
struct InitialSpread {
  double position, velocity, attitude, accel_bias, gyro_bias;
};

InitialSpread initialSpread(const SensorSettings& s) {
  InitialSpread i;
  // The first fix's noise: the filter starts from a fix.
  i.position = s.position.present ? s.position.noise : 1.0;
  // The vehicle starts hovering in place: its speed is known to a few cm/s.
  i.velocity = 0.05;
  // An attitude fix's noise; without one, levelling on the accelerometer at rest gives the tilt
  // to about 1 degree (and the heading is assumed set to that accuracy before take-off).
  i.attitude = s.attitude.present ? s.attitude.noise_deg * M_PI / 180.0 : 1.0 * M_PI / 180.0;
  // The turn-on biases are unknown: their spread, or one second of bias walk if there is none.
  i.accel_bias = std::max(s.imu.accel_bias_init, s.imu.noise.accel_bias_walk);
  i.gyro_bias = std::max(s.imu.gyro_bias_init, s.imu.noise.gyro_bias_walk);
  return i;
}

// The delay after its validity instant with which a fix may reach the filter: the sensor's
// latency plus up to one control period (fixes are handed over at control steps), with room.
double maximumLatency(const SensorSettings& s) {
  const double pos = s.position.present ? s.position.latency : 0.0;
  const double att = s.attitude.present ? s.attitude.latency : 0.0;
  return std::max(pos, att) + 0.05;
}

// The standard deviations the Crazyflie's estimator weighs an external pose with by default:
// crazyflie-firmware src/modules/src/crtp_localization_service.c, extPosStdDev = 0.01 m and
// extQuatStdDev = 4.5e-3 rad (Crazyswarm2 sets 1e-3 and 0.05: estimator.position_std and
// attitude_std).
constexpr double kExtPosStdDev = 0.01;
constexpr double kExtQuatStdDev = 4.5e-3;

CrazyflieKalmanParams crazyflieKalmanParams(const EstimatorSettings& e,
                                            const QuadrotorParams& airframe) {
  CrazyflieKalmanParams p;
  p.drag_b = e.drag;
  p.center_of_pressure = e.center_of_pressure;
  // The world's gravity, as the vehicle's own (the firmware's GRAVITY_MAGNITUDE is 9.81).
  p.gravity = airframe.gravity;
  return p;
}

}  // namespace

VehicleState readVehicleState(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const mjtNum* u = d->qvel + v.qvel_adr;
  VehicleState s;
  s.position = {q[0], q[1], q[2]};
  s.attitude = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
  s.velocity = {u[0], u[1], u[2]};          // free joint: linear velocity in the world frame
  s.angular_velocity = {u[3], u[4], u[5]};  // free joint: angular velocity in the body frame
  return s;
}

StateEstimator::StateEstimator(const EstimatorSettings& estimator, const SensorSettings& sensors,
                               const QuadrotorParams& airframe, std::uint64_t seed,
                               std::size_t vehicle_index)
    : airframe_(airframe),
      sensors_(sensors),
      seed_(sensorSeed(seed, vehicle_index, 3)),
      position_std_(estimator.position_std),
      attitude_std_(estimator.attitude_std) {
  if (estimator.kind == EstimatorKind::Ekf) {
    if (!sensors.imu.present || !sensors.position.present)
      throw std::invalid_argument("the EKF needs an IMU and a position sensor");
    ekf_ = std::make_unique<LatencyCompensatedEkf>(sensors.imu.noise, airframe.gravity,
                                                   maximumLatency(sensors), sensors.imu.rate,
                                                   estimator.predict_rate, estimator.fix_timing);
  } else if (estimator.kind == EstimatorKind::CrazyflieKalman) {
    if (!sensors.imu.present || !sensors.position.present)
      throw std::invalid_argument("the Crazyflie's Kalman estimator needs an IMU and a position");
    kalman_ = std::make_unique<CrazyflieKalmanEstimator>(crazyflieKalmanParams(estimator, airframe),
                                                         estimator.predict_rate);
    if (!(position_std_ > 0.0)) position_std_ = kExtPosStdDev;
    if (!(attitude_std_ > 0.0)) attitude_std_ = kExtQuatStdDev;
  }
}

StateEstimator::~StateEstimator() = default;
StateEstimator::StateEstimator(StateEstimator&&) noexcept = default;
StateEstimator& StateEstimator::operator=(StateEstimator&&) noexcept = default;

void StateEstimator::begin(const mjData* d, const VehicleHandles& v) {
  imu_seen_ = false;
  latest_imu_ = ImuMeasurement{};
  if (kalman_) {
    beginCrazyflieKalman(d, v);
    return;
  }
  if (!ekf_) return;
  const VehicleState truth = readVehicleState(d, v);
  const InitialSpread spread = initialSpread(sensors_);
  std::mt19937_64 rng(seed_);
  std::normal_distribution<double> n(0.0, 1.0);
  const auto draw = [&](double sigma) {
    return Eigen::Vector3d(sigma * n(rng), sigma * n(rng), sigma * n(rng));
  };
  NavigationState x0;
  x0.t = d->time;
  x0.position = truth.position + draw(spread.position);
  x0.velocity = truth.velocity + draw(spread.velocity);
  const Eigen::Vector3d dtheta = draw(spread.attitude);
  x0.attitude =
      (truth.attitude * Eigen::Quaterniond(Eigen::AngleAxisd(dtheta.norm(), dtheta.normalized())))
          .normalized();
  // The biases start at zero: the truth's turn-on bias is the error, drawn by the IMU itself.
  ErrorStateEkf::Covariance P0 = ErrorStateEkf::Covariance::Zero();
  const double sd[5] = {spread.position, spread.velocity, spread.attitude, spread.accel_bias,
                        spread.gyro_bias};
  for (int b = 0; b < 5; ++b) P0.block<3, 3>(3 * b, 3 * b).diagonal().setConstant(sd[b] * sd[b]);
  ekf_->initialise(x0, P0);
}

void StateEstimator::beginCrazyflieKalman(const mjData* d, const VehicleHandles& v) {
  // The firmware's filter has settled on the ground before a flight; here the flight starts in
  // the air, so it starts at the truth with the errors its initial covariance allows for the
  // velocity and attitude drawn from the seeded stream (stdDevInitialVelocity and
  // stdDevInitialAttitude_*, 0.01 each); its position is known to it only by the first fix.
  const VehicleState truth = readVehicleState(d, v);
  const CrazyflieKalmanParams& p = kalman_->core().params();
  std::mt19937_64 rng(seed_);
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Vector3d dv(p.std_initial_velocity * n(rng), p.std_initial_velocity * n(rng),
                           p.std_initial_velocity * n(rng));
  const Eigen::Vector3d dtheta(p.std_initial_attitude_rollpitch * n(rng),
                               p.std_initial_attitude_rollpitch * n(rng),
                               p.std_initial_attitude_yaw * n(rng));
  const Eigen::Quaterniond q =
      (truth.attitude * Eigen::Quaterniond(Eigen::AngleAxisd(dtheta.norm(), dtheta.normalized())))
          .normalized();
  kalman_->initialise(d->time, truth.position, truth.velocity + truth.attitude * dv, q);
}

VehicleState StateEstimator::estimate(const mjData* d, const VehicleHandles& v,
                                      QuadrotorPlant& plant) {
  VehicleState s;
  if (kalman_) {
    s = estimateCrazyflieKalman(d, plant);
  } else if (!ekf_) {
    s = readVehicleState(d, v);
    s.specific_force = plant.trueSpecificForce(d);
  } else {
    SensorReadings& in = readings_;
    plant.takeDelivered(d->time, in);
    for (const ImuMeasurement& z : in.imu) ekf_->addImu(z);
    imu_seen_ = imu_seen_ || !in.imu.empty();
    for (PositionMeasurement z : in.position) {
      if (position_std_ > 0.0) z.sigma = position_std_;
      ekf_->addPosition(z);
    }
    for (AttitudeMeasurement z : in.attitude) {
      if (attitude_std_ > 0.0) z.sigma = attitude_std_;
      ekf_->addAttitude(z);
    }
    const NavigationState& x = ekf_->current();
    s.position = x.position;
    s.velocity = x.velocity;
    s.attitude = x.attitude;
    if (imu_seen_) {
      s.angular_velocity = ekf_->angularVelocity();
      s.specific_force = ekf_->specificForce();
    } else {  // no IMU sample yet (the first control step): the hover it starts in
      s.specific_force = airframe_.gravity * Eigen::Vector3d::UnitZ();
    }
  }
  s.rotor_thrusts = airframe_.thrust_coefficient * plant.rotors().speeds().cwiseAbs2();
  return s;
}

VehicleState StateEstimator::estimateCrazyflieKalman(const mjData* d, QuadrotorPlant& plant) {
  SensorReadings& in = readings_;
  plant.takeDelivered(d->time, in);
  for (const ImuMeasurement& z : in.imu) kalman_->addImu(z);
  if (!in.imu.empty()) {
    latest_imu_ = in.imu.back();
    imu_seen_ = true;
  }
  // Each fix reaches the estimator's queue now (the firmware's extPosStdDev / extQuatStdDev, or
  // the scenario's), positions before attitudes as the halves of one pose.
  for (PositionMeasurement z : in.position) {
    z.sigma = position_std_;
    kalman_->addPosition(z, d->time);
  }
  for (AttitudeMeasurement z : in.attitude) {
    z.sigma = attitude_std_;
    kalman_->addAttitude(z, d->time);
  }
  // Flying: a motor commanded above idle (the Brushless build's rotors have no idle speed here:
  // any commanded speed). The commands are the previous control step's, which held since.
  const bool thrust = plant.rotors().commands().maxCoeff() > 0.0;
  kalman_->advanceTo(d->time, thrust);
  VehicleState s;
  s.position = kalman_->position();
  s.velocity = kalman_->velocity();
  s.attitude = kalman_->attitude();
  if (imu_seen_) {
    // The firmware's controllers read the gyroscope and accelerometer themselves: the latest
    // sample, with no bias estimate (the Kalman estimator has none).
    s.angular_velocity = latest_imu_.gyro;
    s.specific_force = latest_imu_.accel;
  } else {
    s.specific_force = airframe_.gravity * Eigen::Vector3d::UnitZ();
  }
  return s;
}

}  // namespace cosim
