#pragma once
// Pose sensors outside the vehicle or beside the IMU: a position fix (motion capture, GPS) with
// white Gaussian noise of the same standard deviation on each world axis, and an attitude fix
// (motion capture) perturbed on the right by a small rotation, q_meas = q_true (x) Exp(n) with
// n ~ N(0, sigma^2 I) in the body frame: the error model the EKF's attitude update assumes
// (estimation/error_state_ekf.h). Each fix says its own sigma. The measurement is valid at t;
// delivering it `latency` later is the caller's business (the simulator queues it).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <random>

#include "core/ziggurat_normal.h"
#include "estimation/measurements.h"
#include "sim/sensors/sensor_noise_stream.h"
#include "sim/sensors/sensor_settings.h"

namespace cosim {

class PositionSensor {
 public:
  // One seed, one noise stream (sim/sensors/sensor_noise_stream.h): the same numbers every run.
  PositionSensor(const PositionSensorSettings& settings, std::uint64_t seed);
  PositionMeasurement measure(double t, const Eigen::Vector3d& true_position);
  const PositionSensorSettings& settings() const { return settings_; }

 private:
  PositionSensorSettings settings_;
  SensorNoiseEngine rng_;
  ZigguratNormal normal_;  // N(0, 1), core/ziggurat_normal.h
};

class AttitudeSensor {
 public:
  AttitudeSensor(const AttitudeSensorSettings& settings, std::uint64_t seed);
  // true_attitude: body to world.
  AttitudeMeasurement measure(double t, const Eigen::Quaterniond& true_attitude);
  const AttitudeSensorSettings& settings() const { return settings_; }

 private:
  AttitudeSensorSettings settings_;
  SensorNoiseEngine rng_;
  ZigguratNormal normal_;  // N(0, 1), core/ziggurat_normal.h
};

}  // namespace cosim
