#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "estimation/rotation_vector.h"
#include "sim/sensors/imu_sensor.h"
#include "sim/sensors/pose_sensor.h"
#include "sim/sensors/sensor_presets.h"

using namespace cosim;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

// Standard deviation about zero, over all axes of all samples.
double rms(const std::vector<Vector3d>& v) {
  double s = 0.0;
  for (const Vector3d& x : v) s += x.squaredNorm();
  return std::sqrt(s / (3.0 * v.size()));
}

ImuSettings whiteNoiseOnlyImu() {
  ImuSettings s;
  s.present = true;
  s.rate = 500.0;
  s.noise.gyro_noise = 3.3937e-4;
  s.noise.accel_noise = 4.0e-3;
  return s;
}

}  // namespace

TEST(ImuSensor, WhiteNoiseHasTheDensityOverTheRootOfTheSampleInterval) {
  // Kalibr: sigma_d = sigma / sqrt(dt). At 500 Hz: 3.3937e-4 * sqrt(500) = 7.589e-3 rad/s and
  // 4.0e-3 * sqrt(500) = 8.944e-2 m/s^2; at 100 Hz sqrt(5) times less.
  for (const double rate : {500.0, 100.0}) {
    ImuSensor imu(whiteNoiseOnlyImu(), 7);
    const Vector3d w(0.1, -0.2, 0.3), f(0.0, 0.0, 9.81);
    std::vector<Vector3d> gyro_err, accel_err;
    for (int k = 1; k <= 20000; ++k) {
      const ImuMeasurement m = imu.sample(k / rate, w, f);
      gyro_err.push_back(m.gyro - w);
      accel_err.push_back(m.accel - f);
    }
    EXPECT_NEAR(rms(gyro_err), 3.3937e-4 * std::sqrt(rate), 0.02 * 3.3937e-4 * std::sqrt(rate));
    EXPECT_NEAR(rms(accel_err), 4.0e-3 * std::sqrt(rate), 0.02 * 4.0e-3 * std::sqrt(rate));
  }
}

TEST(ImuSensor, BiasRandomWalkSpreadsAsTheWalkTimesTheRootOfTime) {
  // After T = 10 s the walking bias has standard deviation walk * sqrt(T) across runs:
  // 3.8785e-5 * sqrt(10) = 1.2265e-4 rad/s (gyro), 6.0e-3 * sqrt(10) = 1.897e-2 m/s^2 (accel).
  ImuSettings s;
  s.present = true;
  s.rate = 100.0;
  s.noise.gyro_bias_walk = 3.8785e-5;
  s.noise.accel_bias_walk = 6.0e-3;
  std::vector<Vector3d> gyro_bias, accel_bias;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    ImuSensor imu(s, seed);
    for (int k = 1; k <= 1000; ++k) imu.sample(k / s.rate, Vector3d::Zero(), Vector3d::Zero());
    gyro_bias.push_back(imu.gyroBias());
    accel_bias.push_back(imu.accelBias());
  }
  EXPECT_NEAR(rms(gyro_bias), 1.2265e-4, 0.06 * 1.2265e-4);
  EXPECT_NEAR(rms(accel_bias), 1.897e-2, 0.06 * 1.897e-2);
}

TEST(ImuSensor, TurnOnBiasIsDrawnOnceWithItsStandardDeviationAndAddsToEverySample) {
  ImuSettings s;
  s.present = true;
  s.gyro_bias_init = 8.7266e-3;
  s.accel_bias_init = 0.196;
  std::vector<Vector3d> gyro_bias, accel_bias;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    ImuSensor imu(s, seed);
    const Vector3d b_g = imu.gyroBias(), b_a = imu.accelBias();
    ImuMeasurement m;
    for (int k = 1; k <= 5; ++k) m = imu.sample(0.002 * k, Vector3d::Zero(), Vector3d::UnitZ());
    EXPECT_EQ(imu.gyroBias(), b_g);  // no walk: constant
    EXPECT_EQ(m.gyro, b_g);          // no white noise: the sample is truth + bias
    EXPECT_EQ(m.accel, Vector3d::UnitZ() + b_a);
    gyro_bias.push_back(b_g);
    accel_bias.push_back(b_a);
  }
  EXPECT_NEAR(rms(gyro_bias), 8.7266e-3, 0.06 * 8.7266e-3);
  EXPECT_NEAR(rms(accel_bias), 0.196, 0.06 * 0.196);
}

TEST(ImuSensor, SameSeedGivesTheSameSamplesAndAnotherSeedOthers) {
  const ImuSettings s = sensorPreset("mocap").imu;
  ImuSensor a(s, 42), b(s, 42), c(s, 43);
  for (int k = 1; k <= 100; ++k) {
    const double t = k / s.rate;
    const ImuMeasurement ma = a.sample(t, Vector3d::Zero(), Vector3d::UnitZ());
    const ImuMeasurement mb = b.sample(t, Vector3d::Zero(), Vector3d::UnitZ());
    const ImuMeasurement mc = c.sample(t, Vector3d::Zero(), Vector3d::UnitZ());
    ASSERT_EQ(ma.gyro, mb.gyro);
    ASSERT_EQ(ma.accel, mb.accel);
    ASSERT_NE(ma.gyro, mc.gyro);
  }
}

TEST(ImuSensor, RefusesSamplesOutOfTimeOrder) {
  ImuSensor imu(whiteNoiseOnlyImu(), 1);
  imu.sample(0.01, Vector3d::Zero(), Vector3d::Zero());
  EXPECT_THROW(imu.sample(0.01, Vector3d::Zero(), Vector3d::Zero()), std::invalid_argument);
}

TEST(PoseSensor, PositionFixHasTheSettingsNoisePerAxisAndSaysItsSigma) {
  PositionSensorSettings s;
  s.present = true;
  s.noise = 0.5;
  PositionSensor gps(s, 3);
  const Vector3d p(10.0, -5.0, 2.0);
  std::vector<Vector3d> err;
  Vector3d mean = Vector3d::Zero();
  for (int k = 0; k < 10000; ++k) {
    const PositionMeasurement m = gps.measure(0.1 * k, p);
    EXPECT_EQ(m.sigma, 0.5);
    EXPECT_EQ(m.t, 0.1 * k);
    err.push_back(m.position - p);
    mean += (m.position - p) / 10000.0;
  }
  EXPECT_NEAR(rms(err), 0.5, 0.02 * 0.5);
  EXPECT_LT(mean.cwiseAbs().maxCoeff(), 4.0 * 0.5 / std::sqrt(10000.0));
}

TEST(PoseSensor, AttitudeFixIsTheTruthTurnedByABodyFrameErrorOfTheSettingsSigma) {
  AttitudeSensorSettings s;
  s.present = true;
  s.noise_deg = 0.5;
  AttitudeSensor mocap(s, 5);
  const Quaterniond q = Quaterniond(Eigen::AngleAxisd(2.0, Vector3d(1, -1, 2).normalized()));
  std::vector<Vector3d> err;
  for (int k = 0; k < 10000; ++k) {
    const AttitudeMeasurement m = mocap.measure(0.01 * k, q);
    EXPECT_DOUBLE_EQ(m.sigma, 0.5 * M_PI / 180.0);
    err.push_back(rotationVectorFromQuaternion(q.conjugate() * m.attitude));
  }
  EXPECT_NEAR(rms(err), 8.7266e-3, 0.02 * 8.7266e-3);
}

TEST(PoseSensor, SensorsGivenOneSeedDrawIndependentNoise) {
  // The IMU, position and attitude streams are seeded apart (sim/sensors/sensor_noise_stream.h):
  // with noise 1 everywhere, the first draws of the three sensors differ.
  PositionSensorSettings ps;
  ps.noise = 1.0;
  AttitudeSensorSettings as;
  as.noise_deg = 180.0 / M_PI;
  PositionSensor pos(ps, 9);
  AttitudeSensor att(as, 9);
  const Vector3d np = pos.measure(0.0, Vector3d::Zero()).position;
  const Vector3d na =
      rotationVectorFromQuaternion(att.measure(0.0, Quaterniond::Identity()).attitude);
  EXPECT_GT((np - na).norm(), 1e-3);
}

TEST(SensorPresets, IdealSimulatesNoSensor) {
  const SensorSettings s = sensorPreset("ideal");
  EXPECT_TRUE(s.ideal());
  EXPECT_EQ(s.preset, "ideal");
}

TEST(SensorPresets, MocapIsAnAdis16448ImuWithAMillimetrePoseAtOneHundredHertzTenMillisecondsLate) {
  const SensorSettings s = sensorPreset("mocap");
  EXPECT_FALSE(s.ideal());
  ASSERT_TRUE(s.imu.present && s.position.present && s.attitude.present);
  EXPECT_EQ(s.imu.rate, 500.0);
  EXPECT_NEAR(s.imu.noise.gyro_noise, 3.3937e-4, 1e-8);
  EXPECT_NEAR(s.imu.noise.gyro_bias_walk, 3.8785e-5, 1e-9);
  EXPECT_NEAR(s.imu.gyro_bias_init, 8.7266e-3, 1e-7);
  EXPECT_DOUBLE_EQ(s.imu.noise.accel_noise, 4.0e-3);
  EXPECT_DOUBLE_EQ(s.imu.noise.accel_bias_walk, 6.0e-3);
  EXPECT_DOUBLE_EQ(s.imu.accel_bias_init, 0.196);
  EXPECT_EQ(s.position.rate, 100.0);
  EXPECT_EQ(s.position.noise, 0.001);
  EXPECT_EQ(s.position.latency, 0.01);
  EXPECT_EQ(s.attitude.rate, 100.0);
  EXPECT_EQ(s.attitude.noise_deg, 0.5);
  EXPECT_EQ(s.attitude.latency, 0.01);
}

TEST(SensorPresets, OnboardIsTheSameImuWithAGpsPositionAndNoAttitudeSensor) {
  const SensorSettings s = sensorPreset("onboard");
  ASSERT_TRUE(s.imu.present && s.position.present);
  EXPECT_FALSE(s.attitude.present);
  EXPECT_NEAR(s.imu.noise.gyro_noise, 3.3937e-4, 1e-8);
  EXPECT_EQ(s.position.rate, 10.0);
  EXPECT_EQ(s.position.noise, 0.5);
  EXPECT_EQ(s.position.latency, 0.11);
}

TEST(SensorPresets, UnknownNameIsRefusedNamingTheKnownOnes) {
  try {
    sensorPreset("lidar");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'lidar'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("ideal, mocap, onboard"), std::string::npos);
  }
}
