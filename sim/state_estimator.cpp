#include "sim/state_estimator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

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
  if (estimator.name == "ekf") {
    if (!sensors.imu.present || !sensors.position.present)
      throw std::invalid_argument("the EKF needs an IMU and a position sensor");
    ekf_ = std::make_unique<LatencyCompensatedEkf>(sensors.imu.noise, airframe.gravity,
                                                   maximumLatency(sensors), sensors.imu.rate,
                                                   estimator.predict_rate, estimator.fix_timing);
  }
}

StateEstimator::~StateEstimator() = default;
StateEstimator::StateEstimator(StateEstimator&&) noexcept = default;
StateEstimator& StateEstimator::operator=(StateEstimator&&) noexcept = default;

void StateEstimator::begin(const mjData* d, const VehicleHandles& v) {
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
  imu_seen_ = false;
}

VehicleState StateEstimator::estimate(const mjData* d, const VehicleHandles& v,
                                      QuadrotorPlant& plant) {
  VehicleState s;
  if (!ekf_) {
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

}  // namespace cosim
