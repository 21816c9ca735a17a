#pragma once
// What a scenario's `sensors:` and `estimator:` sections ask for (docs/flight_model.md,
// "Sensors" and "Estimator"). Presets and the source of each default are in
// sim/sensors/sensor_presets.cpp; the sensor models in sim/sensors/imu_sensor.h and
// sim/sensors/pose_sensor.h.
#include <Eigen/Core>
#include <cmath>
#include <string>

#include "estimation/fix_timing.h"
#include "estimation/measurements.h"
#include "sim/declared_keys.h"

namespace cosim {

struct ImuSettings {
  bool present = false;
  double rate = 500.0;  // Hz
  ImuNoise noise;
  // Standard deviation of the constant bias each axis has when the IMU powers on (RotorS'
  // "turn-on bias"), drawn once per run from the seeded stream.
  double gyro_bias_init = 0.0;   // rad/s
  double accel_bias_init = 0.0;  // m/s^2

  // The keys (sim/declared_keys.h); noise figures are standard deviations or densities, 0 a
  // perfect sensor, above 1e6 a units mistake.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("rate", rate, 0.1, 1e6, "Hz, at most the physics rate");
    v.number("gyro_noise", noise.gyro_noise, 0.0, 1e6, "rad/s/sqrt(Hz), white noise density");
    v.number("accel_noise", noise.accel_noise, 0.0, 1e6, "m/s^2/sqrt(Hz), white noise density");
    v.number("gyro_bias_walk", noise.gyro_bias_walk, 0.0, 1e6,
             "rad/s^2/sqrt(Hz), the gyro bias' random walk");
    v.number("accel_bias_walk", noise.accel_bias_walk, 0.0, 1e6,
             "m/s^3/sqrt(Hz), the accelerometer bias' random walk");
    v.number("gyro_bias_init", gyro_bias_init, 0.0, 1e6,
             "rad/s, standard deviation of the gyro's turn-on bias");
    v.number("accel_bias_init", accel_bias_init, 0.0, 1e6,
             "m/s^2, standard deviation of the accelerometer's turn-on bias");
  }
};

// A latency of a second or more is a units mistake (a GPS is about 0.1 s late).
constexpr double kMaxSensorLatency = 1.0;

// A position sensor: motion capture (mm, 100+ Hz, a few ms late) or GPS (dm-m, 5-10 Hz, about
// 0.1 s late).
struct PositionSensorSettings {
  bool present = false;
  double rate = 100.0;    // Hz
  double noise = 0.001;   // m, standard deviation per axis
  double latency = 0.01;  // s from the instant measured to the estimator

  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("rate", rate, 0.1, 1e6, "Hz, at most the physics rate");
    v.number("noise", noise, 0.0, 1e6, "m, standard deviation per axis");
    v.number("latency", latency, 0.0, kMaxSensorLatency,
             "s from the instant measured to the estimator, shorter than the run");
  }
};

// An attitude sensor (motion capture).
struct AttitudeSensorSettings {
  bool present = false;
  double rate = 100.0;     // Hz
  double noise_deg = 0.5;  // deg, standard deviation per axis
  double latency = 0.01;   // s

  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("rate", rate, 0.1, 1e6, "Hz, at most the physics rate");
    v.number("noise_deg", noise_deg, 0.0, 1e6, "deg, standard deviation per axis");
    v.number("latency", latency, 0.0, kMaxSensorLatency,
             "s from the instant measured to the estimator, shorter than the run");
  }
};

struct SensorSettings {
  std::string preset = "ideal";  // ideal | mocap | onboard | custom (explicit blocks)
  ImuSettings imu;
  PositionSensorSettings position;
  AttitudeSensorSettings attitude;
  // Ideal: the controller reads the exact state with no delay (no sensor is simulated).
  bool ideal() const { return !imu.present && !position.present && !attitude.present; }

  // The blocks are read with their own declarations (sim/scenario_sensing.cpp).
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.custom("preset", "choice",
             "`ideal`, `mocap` or `onboard` (sim/sensors/sensor_presets.h); blocks change its "
             "values");
    v.custom("imu", "block",
             "an IMU (`sensors.imu`); a block without a preset starts from mocap's");
    v.custom("position", "block", "a position sensor (`sensors.position`)");
    v.custom("attitude", "block", "an attitude sensor (`sensors.attitude`)");
  }
};

// What turns the measurements into the controller's state: the EKF (estimation/
// latency_compensated_ekf.h), the Crazyflie firmware's Kalman estimator (estimation/
// crazyflie_kalman_estimator.h), or the true state.
enum class EstimatorKind { Ekf, CrazyflieKalman, GroundTruth };
inline constexpr ChoiceNames<EstimatorKind, 3> kEstimatorNames{{
    {EstimatorKind::Ekf, "ekf"},
    {EstimatorKind::CrazyflieKalman, "crazyflie_kalman"},
    {EstimatorKind::GroundTruth, "ground_truth"},
}};
// "ekf", ...: as scenarios and metrics.json name it.
inline const char* estimatorName(EstimatorKind kind) {
  return choiceName(kEstimatorNames, kind);
}
// The estimators that filter sensor data.
inline bool isFilter(EstimatorKind kind) {
  return kind != EstimatorKind::GroundTruth;
}

inline constexpr ChoiceNames<FixTiming, 2> kFixTimingNames{{
    {FixTiming::AtValidity, "at_validity"},
    {FixTiming::OnArrival, "on_arrival"},
}};

// estimator: {name: ekf | crazyflie_kalman | ground_truth, predict_rate, fuse, position_std,
// attitude_std, drag, center_of_pressure}. Absent: ground_truth with ideal sensing, ekf otherwise.
struct EstimatorSettings {
  EstimatorKind kind = EstimatorKind::GroundTruth;
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

  // The keys (sim/declared_keys.h); which estimator takes which is checked after them
  // (sim/scenario_sensing.cpp).
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.choice("name", kind, kEstimatorNames,
             "required in the section; without it: ekf with sensors, else ground_truth");
    v.number("predict_rate", predict_rate, 0.1, 1e6,
             "Hz, how often a filter predicts (the Crazyflie's 100 Hz); crazyflie_kalman at most "
             "1000");
    v.choice("fuse", fix_timing, kFixTimingNames,
             "a filter's late fixes: at the time they were valid, or on arrival (crazyflie_kalman: "
             "on_arrival only)");
    v.number("position_std", position_std, 1e-9, 1e3,
             "m, the standard deviation a filter assumes for a position fix; 0: ekf the sensor's, "
             "crazyflie_kalman the firmware's 0.01");
    v.number("attitude_std", attitude_std, 1e-9, M_PI,
             "rad, the same for an attitude fix; 0: ekf the sensor's, crazyflie_kalman 4.5e-3");
    v.vec3("drag", drag, 0.0, 100.0, "1/s, crazyflie_kalman's dragB_x/y/z (0: no drag term)");
    v.vec3("center_of_pressure", center_of_pressure, -1.0, 1.0,
           "m, body frame, crazyflie_kalman's cop_x/y/z");
  }
};

}  // namespace cosim
