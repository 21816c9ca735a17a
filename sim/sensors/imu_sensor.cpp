#include "sim/sensors/imu_sensor.h"

#include <cmath>
#include <stdexcept>

#include "sim/sensors/sensor_noise_stream.h"

namespace cosim {

ImuSensor::ImuSensor(const ImuSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(sensorNoiseStream(seed, SensorKind::kImu)) {
  if (!(settings.rate > 0.0)) throw std::invalid_argument("ImuSensor: rate must be positive");
  gyro_bias_ = settings_.gyro_bias_init * normal3();
  accel_bias_ = settings_.accel_bias_init * normal3();
}

Eigen::Vector3d ImuSensor::normal3() {
  // Drawn one after another (not inside one Eigen expression, whose order is unspecified).
  const double x = normal_(rng_);
  const double y = normal_(rng_);
  const double z = normal_(rng_);
  return {x, y, z};
}

ImuMeasurement ImuSensor::sample(double t, const Eigen::Vector3d& true_angular_velocity_body,
                                 const Eigen::Vector3d& true_specific_force_body) {
  const double dt = sampled_ ? t - last_t_ : 1.0 / settings_.rate;
  if (!(dt > 0.0)) throw std::invalid_argument("ImuSensor: samples must come in time order");
  last_t_ = t;
  sampled_ = true;

  const ImuNoise& n = settings_.noise;
  const double sqrt_dt = std::sqrt(dt);
  gyro_bias_ += n.gyro_bias_walk * sqrt_dt * normal3();
  accel_bias_ += n.accel_bias_walk * sqrt_dt * normal3();

  ImuMeasurement m;
  m.t = t;
  m.gyro = true_angular_velocity_body + gyro_bias_ + (n.gyro_noise / sqrt_dt) * normal3();
  m.accel = true_specific_force_body + accel_bias_ + (n.accel_noise / sqrt_dt) * normal3();
  return m;
}

}  // namespace cosim
