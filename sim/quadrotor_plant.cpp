#include "sim/quadrotor_plant.h"

namespace cosim {

std::uint64_t sensorSeed(std::uint64_t seed, std::size_t vehicle, int sensor) {
  // splitmix64 (Steele, Lea and Flood, "Fast splittable pseudorandom number generators",
  // OOPSLA 2014) of a distinct word per (scenario seed, vehicle, sensor).
  std::uint64_t z =
      seed * 0x9e3779b97f4a7c15ULL + (vehicle << 8) + static_cast<std::uint64_t>(sensor) + 1;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

QuadrotorPlant::QuadrotorPlant(const VehicleHandles& vehicle, const SensorSettings& s,
                               std::uint64_t seed, std::size_t index,
                               const BatterySettings* battery)
    : vehicle_(&vehicle), gravity_(vehicle.params.gravity), rotors_(vehicle.params) {
  if (battery) battery_.emplace(*battery);
  if (s.imu.present) {
    // The vehicle's airframe file may hold its own identified noise densities.
    ImuSettings imu = s.imu;
    if (vehicle.gyro_noise) imu.noise.gyro_noise = *vehicle.gyro_noise;
    if (vehicle.accel_noise) imu.noise.accel_noise = *vehicle.accel_noise;
    imu_ = std::make_unique<ImuSensor>(imu, sensorSeed(seed, index, 0));
    imu_due_.period = imu_due_.next = 1.0 / s.imu.rate;
  }
  if (s.position.present) {
    position_ = std::make_unique<PositionSensor>(s.position, sensorSeed(seed, index, 1));
    position_due_.period = position_due_.next = 1.0 / s.position.rate;
    position_latency_ = s.position.latency;
  }
  if (s.attitude.present) {
    attitude_ = std::make_unique<AttitudeSensor>(s.attitude, sensorSeed(seed, index, 2));
    attitude_due_.period = attitude_due_.next = 1.0 / s.attitude.rate;
    attitude_latency_ = s.attitude.latency;
  }
}

void QuadrotorPlant::commandDuties(const Eigen::Vector4d& duty) {
  duty_ = duty;
  duty_commanded_ = true;
}

double QuadrotorPlant::electricalPower() const {
  // Shaft power tau w with the reaction torque tau = (k_m/k_f) k_f w^2 (sim/battery.h).
  const QuadrotorParams& p = vehicle_->params;
  const double k_q = p.torque_per_thrust * p.thrust_coefficient;
  const double shaft = k_q * rotors_.speeds().cwiseAbs().array().cube().sum();
  return battery_ ? shaft / battery_->settings().drive_efficiency : shaft;
}

double QuadrotorPlant::batteryVoltage() const {
  return battery_ ? battery_->terminalVoltageAtPower(electricalPower()) : 0.0;
}

void QuadrotorPlant::advanceRotors(double dt) {
  if (!battery_) {
    rotors_.advance(dt);
    return;
  }
  const double power = electricalPower();
  const double volts = battery_->terminalVoltageAtPower(power);
  if (duty_commanded_) {
    const QuadrotorParams& p = vehicle_->params;
    Eigen::Vector4d speeds;
    for (int i = 0; i < 4; ++i) speeds[i] = p.steadyRotorSpeed(duty_[i], volts);
    rotors_.command(speeds);
  }
  rotors_.advance(dt);
  battery_->drain(volts > 0.0 ? power / volts : 0.0, dt);
}

Eigen::Vector3d QuadrotorPlant::trueSpecificForce(const mjData* d) const {
  // The free joint's qacc[0..2] is the world-frame acceleration of the body origin (the centre of
  // mass in models/): f = R^T (a - g).
  const mjtNum* a = d->qacc + vehicle_->qvel_adr;
  const mjtNum* q = d->qpos + vehicle_->qpos_adr + 3;
  const Eigen::Matrix3d R =
      Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  return R.transpose() * (Eigen::Vector3d(a[0], a[1], a[2]) + gravity_ * Eigen::Vector3d::UnitZ());
}

void QuadrotorPlant::sense(const mjData* d) {
  const double t = d->time;
  const mjtNum* q = d->qpos + vehicle_->qpos_adr;
  if (imu_ && imu_due_.at(t)) {
    imu_due_.next += imu_due_.period;
    const mjtNum* u = d->qvel + vehicle_->qvel_adr;
    ready_.imu.push_back(imu_->sample(t, Eigen::Vector3d(u[3], u[4], u[5]), trueSpecificForce(d)));
  }
  if (position_ && position_due_.at(t)) {
    position_due_.next += position_due_.period;
    position_queue_.push_back(position_->measure(t, Eigen::Vector3d(q[0], q[1], q[2])));
  }
  if (attitude_ && attitude_due_.at(t)) {
    attitude_due_.next += attitude_due_.period;
    attitude_queue_.push_back(
        attitude_->measure(t, Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized()));
  }
}

void QuadrotorPlant::takeDelivered(double now, SensorReadings& out) {
  // The IMU samples change hands by swapping buffers: both keep their capacity.
  out.imu.swap(ready_.imu);
  ready_.imu.clear();
  out.position.clear();
  out.attitude.clear();
  while (!position_queue_.empty() && position_queue_.front().t + position_latency_ <= now + 1e-9) {
    out.position.push_back(position_queue_.front());
    position_queue_.pop_front();
  }
  while (!attitude_queue_.empty() && attitude_queue_.front().t + attitude_latency_ <= now + 1e-9) {
    out.attitude.push_back(attitude_queue_.front());
    attitude_queue_.pop_front();
  }
}

}  // namespace cosim
