#pragma once
// What a scenario's `sensors:` and `estimator:` sections ask for (docs/flight_model.md,
// "Sensors" and "Estimator"). Presets and the source of each default are in
// sim/sensors/sensor_presets.cpp; the sensor models in sim/sensors/imu_sensor.h and
// sim/sensors/pose_sensor.h.
#include <Eigen/Core>
#include <string>

#include "estimation/fix_timing.h"
#include "estimation/measurements.h"

namespace cosim {

struct ImuSettings {
  bool present = false;
  double rate = 500.0;  // Hz
  ImuNoise noise;
  // Standard deviation of the constant bias each axis has when the IMU powers on (RotorS'
  // "turn-on bias"), drawn once per run from the seeded stream.
  double gyro_bias_init = 0.0;   // rad/s
  double accel_bias_init = 0.0;  // m/s^2
};

// A position sensor: motion capture (mm, 100+ Hz, a few ms late) or GPS (dm-m, 5-10 Hz, about
// 0.1 s late).
struct PositionSensorSettings {
  bool present = false;
  double rate = 100.0;    // Hz
  double noise = 0.001;   // m, standard deviation per axis
  double latency = 0.01;  // s from the instant measured to the estimator
};

// An attitude sensor (motion capture).
struct AttitudeSensorSettings {
  bool present = false;
  double rate = 100.0;     // Hz
  double noise_deg = 0.5;  // deg, standard deviation per axis
  double latency = 0.01;   // s
};

struct SensorSettings {
  std::string preset = "ideal";  // ideal | mocap | onboard | custom (explicit blocks)
  ImuSettings imu;
  PositionSensorSettings position;
  AttitudeSensorSettings attitude;
  // Ideal: the controller reads the exact state with no delay (no sensor is simulated).
  bool ideal() const { return !imu.present && !position.present && !attitude.present; }
};

// estimator: {name: ekf | crazyflie_kalman | ground_truth, predict_rate, fuse, position_std,
// attitude_std, drag, center_of_pressure}. Absent: ground_truth with ideal sensing, ekf otherwise.
struct EstimatorSettings {
  std::string name = "ground_truth";
  // fuse: at_validity (default) fuses a late fix at the instant it was valid for, exactly;
  // on_arrival at the latest prediction when it arrives, as the Crazyflie's Kalman estimator
  // does (estimation/latency_compensated_ekf.h).
  FixTiming fix_timing = FixTiming::AtValidity;
  // Hz, how often the EKF predicts, from the IMU samples averaged since its last prediction
  // (estimation/imu_averager.h); at or above the IMU's rate, at every sample. Default: the
  // Crazyflie's Kalman estimator, PREDICT_RATE = RATE_100_HZ (crazyflie-firmware
  // src/modules/src/estimator/estimator_kalman.c), for every EKF scenario.
  double predict_rate = 100.0;
  // position_std (m) and attitude_std (rad, per axis): the standard deviation the EKF assumes
  // for each position or attitude fix, as the Crazyflie's locSrv.extPosStdDev and
  // extQuatStdDev; 0: the sensor's own noise (sensors.position.noise, sensors.attitude.noise_deg).
  double position_std = 0.0;
  double attitude_std = 0.0;
  // crazyflie_kalman only: the drag term of builds that have it (estimation/
  // crazyflie_kalman_params.h), dragB_x/y/z in 1/s and cop_x/y/z in m, body frame; zero (no
  // term) by default, as in the rig's 2024 build.
  Eigen::Vector3d drag = Eigen::Vector3d::Zero();
  Eigen::Vector3d center_of_pressure = Eigen::Vector3d::Zero();
};

}  // namespace cosim
