#pragma once
// A MEMS IMU: the true body rates and specific force plus, on each axis, white noise, a bias
// that random-walks, and a constant turn-on bias, discretised as in the Kalibr IMU noise model
// (J. Nikolic et al., https://github.com/ethz-asl/kalibr/wiki/IMU-Noise-Model-and-Intrinsics):
// a sample dt after the previous one has white noise of standard deviation density / sqrt(dt)
// and the walking bias a step of standard deviation walk * sqrt(dt) (the first sample takes
// dt = 1 / rate). RotorS' turn-on bias (rotors_gazebo_plugins/src/gazebo_imu_plugin.cpp) is drawn
// once at construction. Pure C++: the simulator hands in the truth.
#include <Eigen/Core>
#include <cstdint>
#include <random>

#include "core/ziggurat_normal.h"
#include "estimation/measurements.h"
#include "sim/sensors/sensor_noise_stream.h"
#include "sim/sensors/sensor_settings.h"

namespace cosim {

class ImuSensor {
 public:
  // One seed, one noise stream (sim/sensors/sensor_noise_stream.h): the same numbers every run.
  ImuSensor(const ImuSettings& settings, std::uint64_t seed);

  // The sample at t (later than the previous sample's t, else std::invalid_argument).
  ImuMeasurement sample(double t, const Eigen::Vector3d& true_angular_velocity_body,
                        const Eigen::Vector3d& true_specific_force_body);

  // The bias in the last sample (turn-on bias plus walk), body frame: what an estimator should
  // find, for tests and logs.
  const Eigen::Vector3d& gyroBias() const { return gyro_bias_; }
  const Eigen::Vector3d& accelBias() const { return accel_bias_; }
  const ImuSettings& settings() const { return settings_; }

 private:
  Eigen::Vector3d normal3();

  ImuSettings settings_;
  SensorNoiseEngine rng_;
  ZigguratNormal normal_;  // N(0, 1), core/ziggurat_normal.h
  Eigen::Vector3d gyro_bias_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_ = Eigen::Vector3d::Zero();
  double last_t_ = 0.0;
  bool sampled_ = false;
};

}  // namespace cosim
