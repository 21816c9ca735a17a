#include "estimation/imu_averager.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace cosim;
using Eigen::Vector3d;

namespace {

ImuMeasurement sample(double t, double gyro_x, double accel_z) {
  ImuMeasurement m;
  m.t = t;
  m.gyro = {gyro_x, 0.0, 0.0};
  m.accel = {0.0, 0.0, accel_z};
  return m;
}

}  // namespace

TEST(ImuAverager, PredictsEveryFifthSampleOfA500HzImuAt100HzWithTheirMean) {
  ImuAverager averager(100.0);
  averager.reset(0.0);
  ImuMeasurement mean;
  // Samples k = 1..10 at 2 ms: gyro k, accel 10 k. Due at k = 5 (t = 0.010) and k = 10.
  for (int k = 1; k <= 10; ++k) {
    const bool due = averager.add(sample(0.002 * k, k, 10.0 * k), mean);
    EXPECT_EQ(due, k % 5 == 0) << k;
    if (k == 5) {
      EXPECT_DOUBLE_EQ(mean.t, 0.010);
      EXPECT_NEAR(mean.gyro.x(), 3.0, 1e-12);    // (1 + 2 + 3 + 4 + 5) / 5
      EXPECT_NEAR(mean.accel.z(), 30.0, 1e-12);  // ten times that
    }
  }
  EXPECT_NEAR(mean.gyro.x(), 8.0, 1e-12);  // (6 + ... + 10) / 5: the first five are forgotten
  EXPECT_DOUBLE_EQ(mean.t, 0.020);
}

TEST(ImuAverager, WeightsEachSampleByTheIntervalItCloses) {
  ImuAverager averager(100.0);
  averager.reset(1.0);
  ImuMeasurement mean;
  // 1 held over 8 ms, then 2 over 2 ms: the held signal's mean over the 10 ms is 1.2 (the plain
  // mean of the two samples would be 1.5).
  EXPECT_FALSE(averager.add(sample(1.008, 1.0, 0.0), mean));
  EXPECT_TRUE(averager.add(sample(1.010, 2.0, 0.0), mean));
  EXPECT_NEAR(mean.gyro.x(), 1.2, 1e-9);
}

TEST(ImuAverager, NextPredictionIsOneIntervalAfterTheLastAsTheFirmwareSchedulesIt) {
  ImuAverager averager(100.0);
  averager.reset(0.0);
  ImuMeasurement mean;
  // Samples every 3 ms: the first at or after 10 ms is 12 ms; the next is due from 22 ms, so at
  // 24 ms (a fixed 10 ms grid would predict at 21 ms).
  for (int k = 1; k <= 8; ++k) {
    const double t = 0.003 * k;
    EXPECT_EQ(averager.add(sample(t, 0.0, 0.0), mean), k == 4 || k == 8) << t;
  }
}

TEST(ImuAverager, AtTheImuRateEverySampleIsItsOwnPredictionToTheBit) {
  ImuAverager averager(500.0);
  averager.reset(0.0);
  ImuMeasurement mean;
  const ImuMeasurement m = sample(0.002, 0.1234567890123, 9.87654321);
  ASSERT_TRUE(averager.add(m, mean));
  EXPECT_EQ(mean.gyro, m.gyro);
  EXPECT_EQ(mean.accel, m.accel);
  EXPECT_THROW(averager.add(m, mean), std::invalid_argument);  // not later than the last
  EXPECT_THROW(ImuAverager(0.0), std::invalid_argument);
}
