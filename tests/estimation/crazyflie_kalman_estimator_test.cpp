#include "estimation/crazyflie_kalman_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "estimation/rotation_vector.h"

using namespace cosim;
using Eigen::Quaterniond;
using Eigen::Vector3d;

namespace {

constexpr double kG = 9.81;
constexpr double kImuRate = 500.0;

ImuMeasurement hoverSample(int k) {
  ImuMeasurement m;
  m.t = k / kImuRate;
  m.accel = Vector3d(0.0, 0.0, kG);
  return m;
}

// A manoeuvring vehicle's IMU and a path its fixes follow that the IMU does not quite match.
ImuMeasurement manoeuvreSample(int k) {
  ImuMeasurement m;
  m.t = k / kImuRate;
  const double t = m.t;
  m.gyro = {0.4 * std::sin(1.3 * t), 0.3 * std::cos(0.7 * t), 0.2 + 0.1 * std::sin(t)};
  m.accel = {0.8 * std::sin(2.0 * t), 0.5 * std::cos(1.1 * t), kG + 0.6 * std::sin(0.9 * t)};
  return m;
}

// Flies `seconds` of the manoeuvre (IMU at 500 Hz, fixes at 100 Hz arriving 11 ms late, control
// steps at 500 Hz) and returns the estimator.
CrazyflieKalmanEstimator flyManoeuvre(double seconds) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d(0.0, 0.0, 1.0), Vector3d::Zero(), Quaterniond::Identity());
  const int steps = static_cast<int>(seconds * kImuRate);
  for (int k = 1; k <= steps; ++k) {
    const double now = k / kImuRate;
    e.addImu(manoeuvreSample(k));
    if (k % 5 == 0) {
      const double valid = now - 0.011;
      e.addPosition({valid, Vector3d(0.3 * std::sin(valid), 0.2 * valid, 1.0), 0.001}, now);
      e.addAttitude(
          {valid, quaternionFromRotationVector(Vector3d(0.1 * std::sin(valid), 0.05, 0.3 * valid)),
           0.05},
          now);
    }
    e.advanceTo(now, true);
  }
  return e;
}

}  // namespace

// The task predicts every 10 ms (RATE_100_HZ at 1 kHz loops) from the mean of the samples taken
// since the last prediction: samples at 2, 4, 6, 8 ms are taken by the loops at those ticks, and
// the prediction at tick 10 (run before that loop takes the 10 ms sample) integrates their mean
// over 10 ms. On the ground the whole accelerometer counts.
TEST(CrazyflieKalmanEstimator, PredictsEveryTenLoopsFromTheMeanOfTheSamplesSince) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d::Zero(), Vector3d::Zero(), Quaterniond::Identity());
  for (int k = 1; k <= 5; ++k) {
    ImuMeasurement m;
    m.t = 0.002 * k;
    m.accel = Vector3d(k, 0.0, kG);  // x: 1, 2, 3, 4, 5 m/s^2
    e.addImu(m);
  }
  e.advanceTo(0.011, false);      // loops 0 .. 10
  EXPECT_EQ(e.predictions(), 2);  // at tick 0 (over 0 s) and at tick 10
  EXPECT_FALSE(e.flying());
  EXPECT_NEAR(e.velocity().x(), 2.5 * 0.01, 1e-12);  // mean of 1..4 over 10 ms
  e.advanceTo(0.1, false);
  EXPECT_EQ(e.predictions(), 10);
}

// The controller at time t sees the state the task left after the loop before t: a fix that
// reaches the vehicle at 20 ms is fused by loop 20, visible from 21 ms on.
TEST(CrazyflieKalmanEstimator, FusesAFixAtTheLoopItArrivesAndShowsItAtTheNext) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d(0.0, 0.0, 1.0), Vector3d::Zero(), Quaterniond::Identity());
  e.addPosition({0.0, Vector3d(0.5, 0.0, 1.0), 0.001}, 0.020);
  e.advanceTo(0.020, true);
  EXPECT_EQ(e.position().x(), 0.0);
  e.advanceTo(0.021, true);
  EXPECT_NEAR(e.position().x(), 0.5, 1e-6);
}

// Flying while thrust is commanded and for 2 s after it stops (supervisor.c's hysteresis).
TEST(CrazyflieKalmanEstimator, FlyingHoldsTwoSecondsAfterTheLastThrust) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d::Zero(), Vector3d::Zero(), Quaterniond::Identity());
  e.advanceTo(0.5, false);
  EXPECT_FALSE(e.flying());
  e.advanceTo(1.0, true);  // last thrust at the loop of 999 ms
  EXPECT_TRUE(e.flying());
  e.advanceTo(2.999, false);  // loop 2998: 1999 ms after
  EXPECT_TRUE(e.flying());
  e.advanceTo(3.0, false);  // loop 2999: 2000 ms after
  EXPECT_FALSE(e.flying());
}

// A body velocity beyond kalman.maxVel (10 m/s) makes the supervisor reset the estimator at the
// next loop: back at its initial position, at rest.
TEST(CrazyflieKalmanEstimator, SupervisorResetsAStateOutOfBounds) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d(1.0, 2.0, 3.0), Vector3d(11.0, 0.0, 0.0), Quaterniond::Identity());
  e.advanceTo(0.001, true);  // loop 0 finds it out of bounds
  EXPECT_EQ(e.resets(), 1u);
  e.advanceTo(0.002, true);  // loop 1 resets
  EXPECT_EQ(e.resets(), 1u);
  EXPECT_NEAR((e.position() - Vector3d(1.0, 2.0, 3.0)).norm(), 0.0, 1e-9);
  EXPECT_LT(e.velocity().norm(), 1e-6);
}

// Started 0.4 m, 0.3 rad of yaw and a couple of degrees of tilt away from a level hovering
// vehicle's fixes (weighed as the firmware does by default: 0.01 m, 4.5e-3 rad), the estimate
// converges to them after 4 s: within a millimetre, at rest to a millimetre per second, and
// within 2 mrad: the firmware folds an attitude correction in only if some component exceeds
// 0.1 mrad (kalmanCoreFinalize), so with a gain near 0.07 a fix the attitude stalls at 1.3 mrad.
TEST(CrazyflieKalmanEstimator, PoseUpdatesConverge) {
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  e.initialise(0.0, Vector3d(0.0, 0.0, 1.0), Vector3d::Zero(),
               quaternionFromRotationVector(Vector3d(0.03, -0.02, 0.0)));
  const Vector3d p(0.3, -0.2, 1.2);
  const Quaterniond q(Eigen::AngleAxisd(0.3, Vector3d::UnitZ()));
  for (int k = 1; k <= 2000; ++k) {
    const double now = k / kImuRate;
    e.addImu(hoverSample(k));
    if (k % 5 == 0) {
      e.addPosition({now, p, 0.01}, now);
      e.addAttitude({now, q, 4.5e-3}, now);
    }
    e.advanceTo(now, true);
  }
  EXPECT_LT((e.position() - p).norm(), 1e-3);
  EXPECT_LT(e.attitude().angularDistance(q), 2e-3);
  EXPECT_GT(e.attitude().angularDistance(q), 1e-3);  // the dead band, as on the vehicle
  EXPECT_LT(e.velocity().norm(), 1e-3);
}

TEST(CrazyflieKalmanEstimator, SameInputsGiveTheSameEstimateToTheBit) {
  const CrazyflieKalmanEstimator a = flyManoeuvre(3.0), b = flyManoeuvre(3.0);
  EXPECT_EQ(a.position(), b.position());
  EXPECT_EQ(a.velocity(), b.velocity());
  EXPECT_EQ(a.attitude().coeffs(), b.attitude().coeffs());
  EXPECT_EQ(a.core().covariance(), b.core().covariance());
  EXPECT_EQ(a.predictions(), 300);
}

TEST(CrazyflieKalmanEstimator, RefusesRatesItsLoopCannotKeep) {
  EXPECT_THROW(CrazyflieKalmanEstimator(CrazyflieKalmanParams{}, 2000.0), std::invalid_argument);
  EXPECT_THROW(CrazyflieKalmanEstimator(CrazyflieKalmanParams{}, 0.0), std::invalid_argument);
  CrazyflieKalmanEstimator e(CrazyflieKalmanParams{}, 100.0);
  EXPECT_THROW(e.addPosition({0.0, Vector3d::Zero(), 0.0}, 0.0), std::invalid_argument);
}
