#pragma once
// The estimator's nominal state: the quantities a flight controller needs (position, velocity,
// attitude) and the IMU biases it must know to use the IMU (the nominal state x of Solà,
// "Quaternion kinematics for the error-state Kalman filter", arXiv:1711.02508, 2017, Sec. 5.1,
// without the gravity vector, which is known here). World frame z up, gravity (0, 0, -g).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cosim {

struct NavigationState {
  double t = 0.0;                                                // s, the instant the state is for
  Eigen::Vector3d position = Eigen::Vector3d::Zero();            // m, world
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();            // m/s, world
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // body to world
  Eigen::Vector3d accel_bias = Eigen::Vector3d::Zero();          // m/s^2, body (added to the truth)
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();           // rad/s, body (added to the truth)
};

}  // namespace cosim
