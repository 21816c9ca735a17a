#pragma once
// What the sensors hand the estimator (sim/sensors/ makes them from the simulated truth; a real
// vehicle's drivers would make them from hardware). Times are the instants a measurement is
// valid for, in seconds of simulated time; a measurement reaches the estimator `latency` later.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cosim {

// One IMU sample, body frame.
struct ImuMeasurement {
  double t = 0.0;
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();   // angular velocity + bias + noise, rad/s
  Eigen::Vector3d accel = Eigen::Vector3d::Zero();  // specific force + bias + noise, m/s^2
};

// A position fix in the world frame (motion capture, GPS), with its per-axis standard deviation.
struct PositionMeasurement {
  double t = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // m
  double sigma = 0.0;                                  // m, per axis
};

// An attitude fix (motion capture): body to world, with its per-axis angle standard deviation.
struct AttitudeMeasurement {
  double t = 0.0;
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();
  double sigma = 0.0;  // rad, per axis (a small rotation error about each body axis)
};

// The IMU's noise in the continuous-time form of the Kalibr IMU noise model (Nikolic et al.,
// https://github.com/ethz-asl/kalibr/wiki/IMU-Noise-Model-and-Intrinsics): white noise densities
// and bias random walks. A sample taken every dt seconds has white noise of standard deviation
// density / sqrt(dt), and the bias takes a step of standard deviation walk * sqrt(dt).
struct ImuNoise {
  double gyro_noise = 0.0;       // rad/s/sqrt(Hz)
  double accel_noise = 0.0;      // m/s^2/sqrt(Hz)
  double gyro_bias_walk = 0.0;   // rad/s^2/sqrt(Hz)
  double accel_bias_walk = 0.0;  // m/s^3/sqrt(Hz)
};

}  // namespace cosim
