#include "sim/sensors/pose_sensor.h"

#include <cmath>

#include "estimation/rotation_vector.h"
#include "sim/sensors/sensor_noise_stream.h"

namespace cosim {

PositionSensor::PositionSensor(const PositionSensorSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(sensorNoiseStream(seed, SensorKind::kPosition)) {}

PositionMeasurement PositionSensor::measure(double t, const Eigen::Vector3d& true_position) {
  // Drawn one after another (the order inside one Eigen expression is unspecified).
  const double nx = normal_(rng_);
  const double ny = normal_(rng_);
  const double nz = normal_(rng_);
  PositionMeasurement m;
  m.t = t;
  m.position = true_position + settings_.noise * Eigen::Vector3d(nx, ny, nz);
  m.sigma = settings_.noise;
  return m;
}

AttitudeSensor::AttitudeSensor(const AttitudeSensorSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(sensorNoiseStream(seed, SensorKind::kAttitude)) {}

AttitudeMeasurement AttitudeSensor::measure(double t, const Eigen::Quaterniond& true_attitude) {
  const double sigma = settings_.noise_deg * M_PI / 180.0;
  const double nx = normal_(rng_);
  const double ny = normal_(rng_);
  const double nz = normal_(rng_);
  AttitudeMeasurement m;
  m.t = t;
  m.attitude = (true_attitude * quaternionFromRotationVector(sigma * Eigen::Vector3d(nx, ny, nz)))
                   .normalized();
  m.sigma = sigma;
  return m;
}

}  // namespace cosim
