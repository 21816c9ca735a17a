#include "sim/sensors/sensor_presets.h"

#include <cmath>
#include <stdexcept>

namespace cosim {
namespace {

// The ADIS16448 defaults of RotorS (ethz-asl/rotors_simulator,
// rotors_gazebo_plugins/include/rotors_gazebo_plugins/gazebo_imu_plugin.h, kDefaultAdis*), the
// IMU of the AscTec Firefly and of many research quadrotors. RotorS models each bias as a
// first-order Gauss-Markov process with a correlation time of 1000 s (gyro) and 300 s (accel);
// this is the pure random walk of the Kalibr model instead, indistinguishable from it over
// flights of minutes (a correlation time of 300 s or more barely pulls the bias back in 120 s).
ImuSettings adis16448() {
  ImuSettings imu;
  imu.present = true;
  imu.rate = 500.0;  // Hz, the control rate of the bundled scenarios (RotorS publishes at 100+ Hz)
  // rad/s/sqrt(Hz), kDefaultAdisGyroscopeNoiseDensity = 2 * 35 / 3600 / 180 * pi = 3.3937e-4.
  imu.noise.gyro_noise = 2.0 * 35.0 / 3600.0 / 180.0 * M_PI;
  // rad/s^2/sqrt(Hz), kDefaultAdisGyroscopeRandomWalk = 2 * 4 / 3600 / 180 * pi = 3.8785e-5.
  imu.noise.gyro_bias_walk = 2.0 * 4.0 / 3600.0 / 180.0 * M_PI;
  // rad/s, kDefaultAdisGyroscopeTurnOnBiasSigma = 0.5 / 180 * pi = 8.7266e-3.
  imu.gyro_bias_init = 0.5 / 180.0 * M_PI;
  // m/s^2/sqrt(Hz), kDefaultAdisAccelerometerNoiseDensity = 2 * 2.0e-3.
  imu.noise.accel_noise = 2.0 * 2.0e-3;
  // m/s^3/sqrt(Hz), kDefaultAdisAccelerometerRandomWalk = 2 * 3.0e-3. An earlier example of ours
  // showed accel_bias_walk 6.0e-5, 100 times less; we take RotorS' value, the cited source.
  imu.noise.accel_bias_walk = 2.0 * 3.0e-3;
  // m/s^2, kDefaultAdisAccelerometerTurnOnBiasSigma = 20e-3 * 9.8 = 0.196.
  imu.accel_bias_init = 20.0e-3 * 9.8;
  return imu;
}

}  // namespace

SensorSettings sensorPreset(const std::string& name) {
  SensorSettings s;
  s.preset = name;
  if (name == "ideal") return s;  // nothing simulated: the controller reads the exact state
  if (name == "mocap") {
    s.imu = adis16448();
    // Motion capture as an indoor Vicon setup gives it (about 1 mm, 0.5 deg, 100 Hz, 10 ms late:
    // Crazyswarm streams Vicon poses at 100 Hz, Preiss et al. ICRA 2017); Vicon
    // positions are millimetre-accurate (P. Merriaux et al., "A Study of Vicon System
    // Positioning Performance", Sensors 17(7):1591, 2017).
    s.position.present = true;
    s.position.rate = 100.0;    // Hz, Preiss et al. 2017
    s.position.noise = 0.001;   // m per axis, Merriaux et al. 2017: mm level
    // s: a round figure; Preiss et al. 2017 measure about 11 ms from camera to controller.
    s.position.latency = 0.01;
    s.attitude.present = true;
    s.attitude.rate = 100.0;     // Hz, Preiss et al. 2017
    s.attitude.noise_deg = 0.5;  // deg per axis, the preset's round figure
    s.attitude.latency = 0.01;   // s, as the position
    return s;
  }
  if (name == "onboard") {
    s.imu = adis16448();
    // A GPS receiver, position only; no attitude sensor (the EKF finds attitude from the IMU).
    s.position.present = true;
    s.position.rate = 10.0;     // Hz, u-blox NEO-M8N datasheet: up to 10 Hz with concurrent GNSS
    s.position.noise = 0.5;     // m per axis, PX4 EKF2 parameter EKF2_GPS_P_NOISE default 0.5 m
    s.position.latency = 0.11;  // s, PX4 EKF2 parameter EKF2_GPS_DELAY default 110 ms
    s.attitude.present = false;
    return s;
  }
  throw std::invalid_argument("unknown sensor preset '" + name +
                              "' (known: ideal, mocap, onboard)");
}

}  // namespace cosim
