#pragma once
// The parameters of the Crazyflie's Kalman estimator (estimation/crazyflie_kalman_core.h), each
// named after its crazyflie-firmware parameter and defaulting to the value of the build the
// Crazyswarm2 rig flew: IMRCLab's fork of crazyflie-firmware, master of November 2024 (its
// kalmanCoreDefaultParams in src/modules/src/kalman_core/kalman_core.c, the "kalman" parameter
// group). Values are SI: the firmware's own units are the same (m, m/s, rad, rad/s).
#include <Eigen/Core>

namespace cosim {

struct CrazyflieKalmanParams {
  // Initial standard deviations: "uncertain of position, but know we're stationary and roughly
  // flat" (kalmanCoreDefaultParams). The position's 100 m gives a variance of 1e4, which the
  // first bounding of the covariance cuts to MAX_COVARIANCE = 100 (as on the vehicle).
  double std_initial_position_xy = 100.0;        // stdDevInitialPosition_xy, m
  double std_initial_position_z = 1.0;           // stdDevInitialPosition_z, m
  double std_initial_velocity = 0.01;            // stdDevInitialVelocity, m/s
  double std_initial_attitude_rollpitch = 0.01;  // stdDevInitialAttitude_rollpitch, rad
  double std_initial_attitude_yaw = 0.01;        // stdDevInitialAttitude_yaw, rad

  // Process noise (addProcessNoiseDt). The firmware's procNoiseAcc_z is 1.0 unless built with
  // CONFIG_ESTIMATOR_KALMAN_GENERAL_PURPOSE (0.5); the rig's build is not.
  double proc_noise_acc_xy = 0.5;          // procNoiseAcc_xy, m/s^2
  double proc_noise_acc_z = 1.0;           // procNoiseAcc_z, m/s^2
  double proc_noise_vel = 0.0;             // procNoiseVel, m/s
  double proc_noise_pos = 0.0;             // procNoisePos, m
  double proc_noise_att = 0.0;             // procNoiseAtt, rad
  double meas_noise_gyro_rollpitch = 0.1;  // measNoiseGyro_rollpitch, rad/s
  double meas_noise_gyro_yaw = 0.1;        // measNoiseGyro_yaw, rad/s

  // The blend of the attitude towards its initial quaternion at every prediction on the ground
  // (ROLLPITCH_ZERO_REVERSION, 0.001; 0 only in builds with the Loco deck's 2D positioning).
  double attitude_reversion = 0.001;

  // Body-frame linear drag (1/s) and the centre of pressure it acts at (m, body frame): the
  // flying prediction's "- dragB (v + omega x cop)" term. Added to bitcraze's firmware in
  // February 2026 ("Account for drag in EKF", with DRAG_B_* and CENTER_OF_PRESSURE_* 0 except
  // for the Flapper); the rig's 2024 build has no such term, which these zeros reproduce.
  Eigen::Vector3d drag_b = Eigen::Vector3d::Zero();              // dragB_x, dragB_y, dragB_z
  Eigen::Vector3d center_of_pressure = Eigen::Vector3d::Zero();  // cop_x, cop_y, cop_z

  // The supervisor's bounds (kalman_supervisor.c, kalman.maxPos and kalman.maxVel): beyond them
  // the estimator is reset at its next loop.
  double max_position = 100.0;  // m, on each axis
  double max_velocity = 10.0;   // m/s, on each body axis

  // Where the state starts: the firmware's kalman.initialX/Y/Z and initialYaw.
  Eigen::Vector3d initial_position = Eigen::Vector3d::Zero();
  double initial_yaw = 0.0;  // rad

  // GRAVITY_MAGNITUDE in the firmware (physicalConstants.h: 9.81 m/s^2).
  double gravity = 9.81;
};

}  // namespace cosim
