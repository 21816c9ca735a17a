#include "estimation/latency_compensated_ekf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "estimation/rotation_vector.h"

using namespace cosim;
using Eigen::Quaterniond;
using Eigen::Vector3d;
using Covariance = ErrorStateEkf::Covariance;

namespace {

constexpr double kG = 9.81;
constexpr double kImuRate = 500.0;

ImuNoise adisNoise() {
  ImuNoise n;
  n.gyro_noise = 3.3937e-4;
  n.gyro_bias_walk = 3.8785e-5;
  n.accel_noise = 4.0e-3;
  n.accel_bias_walk = 6.0e-3;
  return n;
}

// IMU sample k of a manoeuvring vehicle (any smooth signal does: the filter only integrates it).
ImuMeasurement imuSample(int k) {
  ImuMeasurement m;
  m.t = k / kImuRate;
  const double t = m.t;
  m.gyro = {0.4 * std::sin(1.3 * t), 0.3 * std::cos(0.7 * t), 0.2 + 0.1 * std::sin(t)};
  m.accel = {0.8 * std::sin(2.0 * t), 0.5 * std::cos(1.1 * t), kG + 0.6 * std::sin(0.9 * t)};
  return m;
}

// A pose fix, valid at t: a path the IMU signal does not quite match, so each fix moves the
// estimate.
struct PoseFix {
  double t;
  PositionMeasurement position;
  AttitudeMeasurement attitude;
};

PoseFix poseFix(double t) {
  PoseFix f;
  f.t = t;
  f.position = {t, Vector3d(0.3 * std::sin(t), 0.2 * t, 0.05 * std::cos(3 * t)), 0.01};
  f.attitude = {t, quaternionFromRotationVector(Vector3d(0.1 * std::sin(t), 0.05, 0.3 * t)), 0.01};
  return f;
}

NavigationState startState() {
  NavigationState x;
  x.attitude = quaternionFromRotationVector(Vector3d(0.0, 0.05, 0.0));
  return x;
}

Covariance startCovariance() {
  Covariance P = Covariance::Identity() * 1e-2;
  P.block<3, 3>(12, 12) *= 1e-2;
  return P;
}

// The reference: a plain ErrorStateEkf that fuses every fix on time and in time order
// (position before attitude at one instant), each at its own instant within its IMU interval.
struct Reference {
  ErrorStateEkf ekf{adisNoise(), kG};
  Reference() { ekf.initialise(startState(), startCovariance()); }
  void run(int imu_steps, std::vector<PoseFix> fixes) {
    std::sort(fixes.begin(), fixes.end(),
              [](const PoseFix& a, const PoseFix& b) { return a.t < b.t; });
    std::size_t next = 0;
    for (int k = 1; k <= imu_steps; ++k) {
      const ImuMeasurement imu = imuSample(k);
      for (; next < fixes.size() && fixes[next].t <= imu.t; ++next) {
        ekf.predictTo(fixes[next].t, imu);
        ekf.updatePosition(fixes[next].position);
        ekf.updateAttitude(fixes[next].attitude);
      }
      ekf.predict(imu);
    }
  }
};

double stateDifference(const NavigationState& a, const NavigationState& b) {
  return std::max({(a.position - b.position).norm(), (a.velocity - b.velocity).norm(),
                   rotationVectorFromQuaternion(a.attitude.conjugate() * b.attitude).norm(),
                   (a.accel_bias - b.accel_bias).norm(), (a.gyro_bias - b.gyro_bias).norm(),
                   std::abs(a.t - b.t)});
}

// Fixes every 10 ms, each valid 0.7 ms after an IMU sample (between two samples).
std::vector<PoseFix> mocapFixes(double until) {
  std::vector<PoseFix> fixes;
  for (int i = 1; 0.01 * i + 0.0007 < until; ++i) fixes.push_back(poseFix(0.01 * i + 0.0007));
  return fixes;
}

}  // namespace

TEST(LatencyCompensatedEkf, FixesDelayedByTenMillisecondsGiveTheOnTimeInOrderResult) {
  const int steps = 1000;  // 2 s at 500 Hz
  const std::vector<PoseFix> fixes = mocapFixes(steps / kImuRate);
  Reference ref;
  ref.run(steps, fixes);

  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.012, kImuRate, kImuRate);
  ekf.initialise(startState(), startCovariance());
  std::size_t delivered = 0;
  for (int k = 1; k <= steps; ++k) {
    const ImuMeasurement imu = imuSample(k);
    ekf.addImu(imu);
    // Delivered 10 ms late, at the first IMU sample at or after t + 0.01.
    for (; delivered < fixes.size() && fixes[delivered].t + 0.01 <= imu.t + 1e-12; ++delivered) {
      EXPECT_TRUE(ekf.addPosition(fixes[delivered].position));
      EXPECT_TRUE(ekf.addAttitude(fixes[delivered].attitude));
    }
  }
  // The last fixes are not delivered yet at 2 s: run the reference only to the delivered ones.
  Reference ref_delivered;
  ref_delivered.run(steps, std::vector<PoseFix>(fixes.begin(), fixes.begin() + delivered));
  EXPECT_EQ(delivered, fixes.size() - 1);
  EXPECT_LT(stateDifference(ekf.current(), ref_delivered.ekf.state()), 1e-9);
  EXPECT_LT((ekf.covariance() - ref_delivered.ekf.covariance()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(ekf.droppedMeasurements(), 0u);
  // And the fixes matter: without the last one the state differs from the full reference.
  EXPECT_GT((ekf.current().position - ref.ekf.state().position).norm(), 1e-6);
}

TEST(LatencyCompensatedEkf, FixesArrivingOutOfOrderGiveTheInOrderResult) {
  const int steps = 600;
  std::vector<PoseFix> fixes;
  for (int i = 0; i < 60; ++i) fixes.push_back(poseFix(0.0053 + 0.019 * i));  // 52 Hz, off-grid
  Reference ref;
  ref.run(steps, fixes);

  // GPS-like: up to 0.1 s late, fixes and their position/attitude halves delivered in a
  // scrambled order (each fix arrives 0.02-0.1 s late, depending on its index).
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.11, kImuRate, kImuRate);
  ekf.initialise(startState(), startCovariance());
  std::vector<bool> pos_sent(fixes.size()), att_sent(fixes.size());
  for (int k = 1; k <= steps; ++k) {
    const ImuMeasurement imu = imuSample(k);
    ekf.addImu(imu);
    for (std::size_t i = fixes.size(); i-- > 0;) {  // newest first
      const double delay_p = 0.02 + 0.08 * ((i * 7) % 10) / 10.0;
      const double delay_a = 0.02 + 0.08 * ((i * 3 + 5) % 10) / 10.0;
      if (!att_sent[i] && fixes[i].t + delay_a <= imu.t) {
        EXPECT_TRUE(ekf.addAttitude(fixes[i].attitude));
        att_sent[i] = true;
      }
      if (!pos_sent[i] && fixes[i].t + delay_p <= imu.t) {
        EXPECT_TRUE(ekf.addPosition(fixes[i].position));
        pos_sent[i] = true;
      }
    }
  }
  // Every fix was valid before the last sample; the ones still late are delivered now.
  for (std::size_t i = 0; i < fixes.size(); ++i) {
    if (!att_sent[i]) {
      EXPECT_TRUE(ekf.addAttitude(fixes[i].attitude));
    }
    if (!pos_sent[i]) {
      EXPECT_TRUE(ekf.addPosition(fixes[i].position));
    }
  }
  EXPECT_LT(stateDifference(ekf.current(), ref.ekf.state()), 1e-9);
  EXPECT_LT((ekf.covariance() - ref.ekf.covariance()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(ekf.droppedMeasurements(), 0u);
}

TEST(LatencyCompensatedEkf, PositionAndAttitudeOfOneInstantGiveTheSameStateInEitherArrivalOrder) {
  LatencyCompensatedEkf a(adisNoise(), kG, 0.02, kImuRate, kImuRate),
      b(adisNoise(), kG, 0.02, kImuRate, kImuRate);
  a.initialise(startState(), startCovariance());
  b.initialise(startState(), startCovariance());
  for (int k = 1; k <= 10; ++k) {
    a.addImu(imuSample(k));
    b.addImu(imuSample(k));
  }
  const PoseFix f = poseFix(0.0111);
  a.addPosition(f.position);
  a.addAttitude(f.attitude);
  b.addAttitude(f.attitude);
  b.addPosition(f.position);
  EXPECT_EQ(stateDifference(a.current(), b.current()), 0.0);  // the same operations, bit for bit
  EXPECT_TRUE(a.covariance() == b.covariance());
}

TEST(LatencyCompensatedEkf, FixValidAfterTheLatestImuSampleWaitsForIt) {
  const std::vector<PoseFix> fixes = {poseFix(0.0151)};  // between samples 7 and 8
  Reference ref;
  ref.run(20, fixes);

  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.01, kImuRate, kImuRate);
  ekf.initialise(startState(), startCovariance());
  for (int k = 1; k <= 3; ++k) ekf.addImu(imuSample(k));
  const NavigationState before = ekf.current();
  EXPECT_TRUE(ekf.addPosition(fixes[0].position));
  EXPECT_TRUE(ekf.addAttitude(fixes[0].attitude));
  EXPECT_EQ(ekf.waitingMeasurements(), 2u);
  EXPECT_EQ(stateDifference(ekf.current(), before), 0.0);  // nothing fused yet
  for (int k = 4; k <= 20; ++k) ekf.addImu(imuSample(k));
  EXPECT_EQ(ekf.waitingMeasurements(), 0u);
  EXPECT_LT(stateDifference(ekf.current(), ref.ekf.state()), 1e-9);
}

TEST(LatencyCompensatedEkf, FixOlderThanTheHistoryIsDroppedAndCounted) {
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.02, kImuRate, kImuRate);
  ekf.initialise(startState(), startCovariance());
  for (int k = 1; k <= 50; ++k) ekf.addImu(imuSample(k));  // to t = 0.1 s
  // 0.02 s at 500 Hz: 10 steps plus the two spare, so the window opens at 0.1 - 11 / 500.
  EXPECT_EQ(ekf.historyCapacity(), 12u);
  EXPECT_NEAR(ekf.windowStart(), 0.1 - 11.0 / kImuRate, 1e-12);
  const NavigationState before = ekf.current();
  const Covariance P_before = ekf.covariance();

  EXPECT_FALSE(ekf.addPosition(poseFix(0.05).position));               // 50 ms old
  EXPECT_FALSE(ekf.addAttitude(poseFix(ekf.windowStart()).attitude));  // exactly at the edge
  EXPECT_EQ(ekf.droppedMeasurements(), 2u);
  EXPECT_EQ(stateDifference(ekf.current(), before), 0.0);
  EXPECT_TRUE(ekf.covariance() == P_before);

  // One exactly max_latency old is still fused.
  EXPECT_TRUE(ekf.addPosition(poseFix(0.1 - 0.02).position));
  EXPECT_EQ(ekf.droppedMeasurements(), 2u);
  EXPECT_GT((ekf.current().position - before.position).norm(), 1e-4);
}

TEST(LatencyCompensatedEkf, ReportsTheLatestSampleCorrectedByTheCurrentBiases) {
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.01, kImuRate, kImuRate);
  NavigationState x0 = startState();
  x0.accel_bias = {0.1, -0.1, 0.05};
  x0.gyro_bias = {0.01, 0.0, -0.02};
  ekf.initialise(x0, startCovariance());
  EXPECT_EQ(ekf.angularVelocity(), Vector3d::Zero());
  for (int k = 1; k <= 5; ++k) ekf.addImu(imuSample(k));
  ekf.addPosition(poseFix(0.005).position);  // moves the bias estimates
  const NavigationState& x = ekf.current();
  EXPECT_NE(x.accel_bias, x0.accel_bias);
  EXPECT_LT((ekf.angularVelocity() - (imuSample(5).gyro - x.gyro_bias)).norm(), 1e-15);
  EXPECT_LT((ekf.specificForce() - (imuSample(5).accel - x.accel_bias)).norm(), 1e-15);
}

TEST(LatencyCompensatedEkf, RefusesImuSamplesOutOfTimeOrder) {
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.01, kImuRate, kImuRate);
  ekf.initialise(startState(), startCovariance());
  ekf.addImu(imuSample(3));
  EXPECT_THROW(ekf.addImu(imuSample(2)), std::invalid_argument);
  EXPECT_THROW(ekf.addImu(imuSample(3)), std::invalid_argument);
}

namespace {

// The reference at a prediction rate of 100 Hz: a plain ErrorStateEkf that predicts with the
// mean of each five 500 Hz samples over their 10 ms, fusing every fix on time within its
// interval (predicted to it with that interval's mean).
ErrorStateEkf referenceAt100Hz(int imu_steps, const std::vector<PoseFix>& fixes) {
  ErrorStateEkf ekf(adisNoise(), kG);
  ekf.initialise(startState(), startCovariance());
  std::size_t next = 0;
  for (int k = 5; k <= imu_steps; k += 5) {
    ImuMeasurement mean;
    mean.t = imuSample(k).t;
    for (int j = k - 4; j <= k; ++j) {
      mean.gyro += imuSample(j).gyro / 5.0;
      mean.accel += imuSample(j).accel / 5.0;
    }
    for (; next < fixes.size() && fixes[next].t <= mean.t; ++next) {
      ekf.predictTo(fixes[next].t, mean);
      ekf.updatePosition(fixes[next].position);
      ekf.updateAttitude(fixes[next].attitude);
    }
    ekf.predict(mean);
  }
  return ekf;
}

}  // namespace

TEST(LatencyCompensatedEkf, PredictingAt100HzIntegratesTheAveragedSamplesOverEachInterval) {
  const int steps = 1000;  // 2 s at 500 Hz: 200 predictions
  const std::vector<PoseFix> fixes = mocapFixes(steps / kImuRate);
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.012 + 0.01, kImuRate, 100.0);
  ekf.initialise(startState(), startCovariance());
  std::size_t delivered = 0;
  for (int k = 1; k <= steps; ++k) {
    ekf.addImu(imuSample(k));
    for (; delivered < fixes.size() && fixes[delivered].t + 0.011 <= imuSample(k).t + 1e-12;
         ++delivered) {
      EXPECT_TRUE(ekf.addPosition(fixes[delivered].position));
      EXPECT_TRUE(ekf.addAttitude(fixes[delivered].attitude));
    }
    if (k == 7) {  // between predictions: the estimate is still the one of 10 ms
      EXPECT_DOUBLE_EQ(ekf.current().t, 0.010);
      // ... while the body rates are the latest sample's, less the bias estimate.
      EXPECT_LT((ekf.angularVelocity() - (imuSample(7).gyro - ekf.current().gyro_bias)).norm(),
                1e-15);
    }
  }
  const ErrorStateEkf ref =
      referenceAt100Hz(steps, std::vector<PoseFix>(fixes.begin(), fixes.begin() + delivered));
  EXPECT_LT(stateDifference(ekf.current(), ref.state()), 1e-9);
  EXPECT_LT((ekf.covariance() - ref.covariance()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(ekf.droppedMeasurements(), 0u);
  // 0.022 s at 100 Hz: 3 steps plus the two spare.
  EXPECT_EQ(ekf.historyCapacity(), 5u);

  // And it is a different filter from the one predicting at every sample: the same fixes and
  // samples give a state apart by more than rounding (the mean of a sample's interval is not
  // its integral over the attitude's turn).
  LatencyCompensatedEkf every(adisNoise(), kG, 0.022, kImuRate, kImuRate);
  every.initialise(startState(), startCovariance());
  delivered = 0;
  for (int k = 1; k <= steps; ++k) {
    every.addImu(imuSample(k));
    for (; delivered < fixes.size() && fixes[delivered].t + 0.011 <= imuSample(k).t + 1e-12;
         ++delivered) {
      every.addPosition(fixes[delivered].position);
      every.addAttitude(fixes[delivered].attitude);
    }
  }
  EXPECT_GT(stateDifference(ekf.current(), every.current()), 1e-7);
  EXPECT_LT(stateDifference(ekf.current(), every.current()), 1e-2);
}

// On arrival (the Crazyflie's Kalman estimator): a pose valid at 10.7 ms that arrives after the
// sample at 20 ms is fused into the state predicted to 20 ms, as a plain filter that updates
// there with the old pose; fused at its validity instead, it gives another state (the latency the
// firmware leaves in the estimate).
TEST(LatencyCompensatedEkf, OnArrivalFusesALateFixIntoTheLatestPrediction) {
  const PoseFix fix = poseFix(0.0107);
  ErrorStateEkf plain(adisNoise(), kG);
  plain.initialise(startState(), startCovariance());
  for (int k = 1; k <= 10; ++k) plain.predict(imuSample(k));
  plain.updatePosition({0.02, fix.position.position, fix.position.sigma});
  plain.updateAttitude({0.02, fix.attitude.attitude, fix.attitude.sigma});
  for (int k = 11; k <= 15; ++k) plain.predict(imuSample(k));

  const auto fly = [&](FixTiming timing) {
    LatencyCompensatedEkf ekf(adisNoise(), kG, 0.011, kImuRate, kImuRate, timing);
    ekf.initialise(startState(), startCovariance());
    for (int k = 1; k <= 10; ++k) ekf.addImu(imuSample(k));
    EXPECT_TRUE(ekf.addPosition(fix.position));
    EXPECT_TRUE(ekf.addAttitude(fix.attitude));
    for (int k = 11; k <= 15; ++k) ekf.addImu(imuSample(k));
    return std::make_pair(ekf.current(), ekf.covariance());
  };
  const auto [on_arrival, P_on_arrival] = fly(FixTiming::OnArrival);
  EXPECT_LT(stateDifference(on_arrival, plain.state()), 1e-12);
  EXPECT_LT((P_on_arrival - plain.covariance()).cwiseAbs().maxCoeff(), 1e-15);

  Reference on_time;
  on_time.run(15, {fix});
  const NavigationState at_validity = fly(FixTiming::AtValidity).first;
  EXPECT_LT(stateDifference(at_validity, on_time.ekf.state()), 1e-9);
  // The 9.3 ms between validity and fusion moves the estimate by millimetres here.
  EXPECT_GT((at_validity.position - on_arrival.position).norm(), 1e-4);
}

// On arrival no fix is too old: one valid long before the history began is still fused.
TEST(LatencyCompensatedEkf, OnArrivalNeverDropsAFix) {
  LatencyCompensatedEkf ekf(adisNoise(), kG, 0.01, kImuRate, kImuRate, FixTiming::OnArrival);
  ekf.initialise(startState(), startCovariance());
  for (int k = 1; k <= 100; ++k) ekf.addImu(imuSample(k));
  const NavigationState before = ekf.current();
  EXPECT_TRUE(ekf.addPosition(poseFix(0.001).position));
  EXPECT_EQ(ekf.droppedMeasurements(), 0u);
  EXPECT_GT((ekf.current().position - before.position).norm(), 1e-3);
}
