// The error-state EKF with its latency compensation, fed by the sensor models on an exactly known
// flight: is it consistent (its covariance matches its actual errors), and does its error follow
// the sensors' noise?
//
// Consistency is checked by the Monte-Carlo average NEES (normalised estimation error squared;
// Bar-Shalom, Li and Kirubarajan, "Estimation with Applications to Tracking and Navigation",
// 2001, Sec. 5.4.2): over M independent runs, at each sampled instant, the mean of
// e^T P^-1 e is, for a consistent filter, chi-square with M n degrees of freedom divided by M.
// The test averages it also over the sampled instants and requires the result inside the two-
// sided 95% interval of that distribution, and most instants inside it too. The error is the
// full 15-dim error state (position, velocity, attitude, both biases): a filter can be right
// about its position and still overconfident about a bias, and the bias then leaks into the
// position later. The one exception is the GPS-only hover, see there.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <random>
#include <vector>

#include "estimation/latency_compensated_ekf.h"
#include "estimation/rotation_vector.h"
#include "sim/sensors/imu_sensor.h"
#include "sim/sensors/pose_sensor.h"
#include "sim/sensors/sensor_presets.h"
#include "synthetic_flight.h"

using namespace cosim;
using cosim::test::SyntheticFlight;
using cosim::test::TruthSample;
using Eigen::Vector3d;
using Covariance = ErrorStateEkf::Covariance;

namespace {

constexpr double kG = SyntheticFlight::kGravity;

// The chi-square quantile by the Wilson-Hilferty approximation (E. B. Wilson and M. M. Hilferty,
// "The distribution of chi-square", PNAS 17(12):684-688, 1931): (X/k)^(1/3) is nearly normal
// with mean 1 - 2/(9k) and variance 2/(9k); for k = 300 it is within 0.1% of the exact value.
double chiSquareQuantile(double dof, double z) {
  const double h = 2.0 / (9.0 * dof);
  const double c = 1.0 - h + z * std::sqrt(h);
  return dof * c * c * c;
}
constexpr double kZ975 = 1.959963984540054;  // standard normal 97.5% quantile

struct Run {
  std::vector<double> nees;      // at each sampled instant
  double position_sq_sum = 0.0;  // of the 3D position error, over the same instants
};

// Flies `flight` for `duration` s with the sensors of `sensors` (noise and latencies from there)
// feeding the latency-compensated EKF; the filter starts from the truth displaced by an error
// drawn from its own initial covariance, with zero bias estimates (the IMU's turn-on biases are
// drawn with the same standard deviations). Samples the error every 0.25 s from 0.5 s on.
// The NEES is that of the first `dims` components of the error state (15: all; 6: position and
// velocity).
Run flyWithEkf(const SyntheticFlight& flight, const SensorSettings& sensors, std::uint64_t seed,
               double duration, int dims) {
  const double rate = sensors.imu.rate;
  ImuSensor imu(sensors.imu, seed);
  std::optional<PositionSensor> pos;
  std::optional<AttitudeSensor> att;
  if (sensors.position.present) pos.emplace(sensors.position, seed);
  if (sensors.attitude.present) att.emplace(sensors.attitude, seed);

  // Fixes are delivered at the first IMU sample at or after t + latency: up to one IMU period
  // more than the latency behind.
  const double max_latency =
      std::max(pos ? sensors.position.latency : 0.0, att ? sensors.attitude.latency : 0.0) +
      1.0 / rate;
  // Predicting at the scenarios' default rate (100 Hz) from the averaged samples.
  LatencyCompensatedEkf ekf(sensors.imu.noise, kG, max_latency, rate,
                            EstimatorSettings{}.predict_rate);

  const double sd[5] = {pos ? sensors.position.noise : 1.0, 0.1, 1.0 * M_PI / 180.0,
                        sensors.imu.accel_bias_init, sensors.imu.gyro_bias_init};
  Covariance P0 = Covariance::Zero();
  for (int b = 0; b < 5; ++b) P0.block<3, 3>(3 * b, 3 * b).diagonal().setConstant(sd[b] * sd[b]);
  std::mt19937_64 rng(seed * 0x9e3779b97f4a7c15ull + 12345);
  std::normal_distribution<double> normal;
  auto draw = [&](double s) {
    const double x = normal(rng), y = normal(rng), z = normal(rng);
    return Vector3d(s * x, s * y, s * z);
  };
  const TruthSample t0 = flight.at(0.0);
  NavigationState x0;  // truth = estimate (+) error
  x0.position = t0.position - draw(sd[0]);
  x0.velocity = t0.velocity - draw(sd[1]);
  x0.attitude = t0.attitude * quaternionFromRotationVector(-draw(sd[2]));
  ekf.initialise(x0, P0);

  std::deque<PositionMeasurement> pos_queue;
  std::deque<AttitudeMeasurement> att_queue;
  int next_pos = 1, next_att = 1;
  const int steps = static_cast<int>(std::lround(duration * rate));
  const int sample_every = static_cast<int>(std::lround(0.25 * rate));
  Run run;
  for (int k = 1; k <= steps; ++k) {
    const double t = k / rate;
    const TruthSample truth = flight.at(t);
    ekf.addImu(imu.sample(t, truth.angular_velocity_body, truth.specific_force_body));
    for (; pos && next_pos / sensors.position.rate <= t + 1e-9; ++next_pos) {
      const double tm = next_pos / sensors.position.rate;
      pos_queue.push_back(pos->measure(tm, flight.at(tm).position));
    }
    for (; att && next_att / sensors.attitude.rate <= t + 1e-9; ++next_att) {
      const double tm = next_att / sensors.attitude.rate;
      att_queue.push_back(att->measure(tm, flight.at(tm).attitude));
    }
    for (; !pos_queue.empty() && pos_queue.front().t + sensors.position.latency <= t + 1e-9;
         pos_queue.pop_front()) {
      EXPECT_TRUE(ekf.addPosition(pos_queue.front()));
    }
    for (; !att_queue.empty() && att_queue.front().t + sensors.attitude.latency <= t + 1e-9;
         att_queue.pop_front()) {
      EXPECT_TRUE(ekf.addAttitude(att_queue.front()));
    }

    if (k % sample_every != 0 || t < 0.5) continue;
    const NavigationState& x = ekf.current();  // at the latest prediction (<= t)
    const TruthSample then = flight.at(x.t);
    Eigen::Matrix<double, 15, 1> e;
    e << then.position - x.position, then.velocity - x.velocity,
        rotationVectorFromQuaternion(x.attitude.conjugate() * then.attitude),
        imu.accelBias() - x.accel_bias, imu.gyroBias() - x.gyro_bias;
    const Eigen::VectorXd e_n = e.head(dims);
    const Eigen::MatrixXd P_n = ekf.covariance().topLeftCorner(dims, dims);
    run.nees.push_back(e_n.dot(P_n.llt().solve(e_n)));
    run.position_sq_sum += e.head<3>().squaredNorm();
  }
  EXPECT_EQ(ekf.droppedMeasurements(), 0u);
  return run;
}

struct Consistency {
  double anees;          // average NEES over runs and instants
  double lower, upper;   // the two-sided 95% interval for the average over runs
  double inside;         // fraction of instants whose run-average lies in the interval
  double position_rmse;  // m, over runs and instants
};

Consistency monteCarlo(const SyntheticFlight& flight, const SensorSettings& sensors, int runs,
                       double duration, int dims = 15) {
  std::vector<Run> all;
  for (int i = 0; i < runs; ++i) {
    all.push_back(flyWithEkf(flight, sensors, 1000 + i, duration, dims));
  }
  const std::size_t instants = all[0].nees.size();
  const double n = dims;
  Consistency c;
  c.lower = chiSquareQuantile(runs * n, -kZ975) / runs;
  c.upper = chiSquareQuantile(runs * n, kZ975) / runs;
  double sum = 0.0, sq = 0.0;
  int inside = 0;
  for (std::size_t j = 0; j < instants; ++j) {
    double mean = 0.0;
    for (const Run& r : all) mean += r.nees[j] / runs;
    sum += mean;
    inside += mean >= c.lower && mean <= c.upper;
  }
  for (const Run& r : all) sq += r.position_sq_sum;
  c.anees = sum / instants;
  c.inside = static_cast<double>(inside) / instants;
  c.position_rmse = std::sqrt(sq / (runs * instants));
  return c;
}

void report(const char* what, const Consistency& c) {
  std::printf(
      "[ NEES     ] %s: average NEES %.2f (95%% interval [%.2f, %.2f]), %.0f%% of instants "
      "inside, position RMSE %.4f m\n",
      what, c.anees, c.lower, c.upper, 100.0 * c.inside, c.position_rmse);
}

const SyntheticFlight kHover = SyntheticFlight::hover({0.0, 0.0, 2.0});
// A = 4 m, 3 m/s at the crossing; one lap is 11.85 s.
const SyntheticFlight kFigureEight = SyntheticFlight::figureEight({0.0, 0.0, 2.0}, 4.0, 3.0);
constexpr int kRuns = 20;

}  // namespace

TEST(SyntheticFlight, BodyRatesAndSpecificForceAreThoseOfTheAttitudeAndTrajectory) {
  // Central differences of the analytic attitude and velocity (error O(h^2) ~ 1e-9 here).
  const double h = 1e-4;
  for (double t = 0.0; t < 12.0; t += 0.37) {
    const TruthSample s = kFigureEight.at(t), a = kFigureEight.at(t - h),
                      b = kFigureEight.at(t + h);
    const Vector3d w_fd =
        rotationVectorFromQuaternion(a.attitude.conjugate() * b.attitude) / (2 * h);
    EXPECT_LT((w_fd - s.angular_velocity_body).norm(), 1e-7) << "t = " << t;
    const Vector3d acc_fd = (b.velocity - a.velocity) / (2 * h);
    const Vector3d f = s.attitude.conjugate() * (acc_fd + kG * Vector3d::UnitZ());
    EXPECT_LT((f - s.specific_force_body).norm(), 1e-6) << "t = " << t;
    EXPECT_LT(((b.position - a.position) / (2 * h) - s.velocity).norm(), 1e-6);
  }
  EXPECT_NEAR(kFigureEight.at(0.0).velocity.norm(), 3.0, 1e-12);
  // Rolling and pitching at once gives a yaw rate even with the heading held.
  EXPECT_GT(std::abs(kFigureEight.at(1.3).angular_velocity_body.z()), 1e-4);
}

TEST(EkfConsistency, MocapHoverOfAMinuteHasAChiSquareConsistentNees) {
  const Consistency c = monteCarlo(kHover, sensorPreset("mocap"), kRuns, 60.0);
  report("mocap hover 60 s", c);
  EXPECT_GT(c.anees, c.lower);
  EXPECT_LT(c.anees, c.upper);
  EXPECT_GE(c.inside, 0.9);
}

TEST(EkfConsistency, MocapFigureEightHasAChiSquareConsistentNees) {
  const Consistency c = monteCarlo(kFigureEight, sensorPreset("mocap"), kRuns, 24.0);
  report("mocap figure-eight 24 s", c);
  EXPECT_GT(c.anees, c.lower);
  EXPECT_LT(c.anees, c.upper);
  EXPECT_GE(c.inside, 0.9);
}

TEST(EkfConsistency, OnboardHoverOfAMinuteHasAChiSquareConsistentPositionAndVelocityNees) {
  // Hovering with GPS alone, yaw is unobservable (no magnetometer): it drifts with the gyro's
  // turn-on bias (0.5 deg/s), to a standard deviation of 0.36 rad after 60 s, and with it the
  // body axes in which the accelerometer's horizontal bias is expressed. At such angles the
  // filter's first-order error model no longer holds and it grows overconfident: the 15-dim
  // average NEES of this run is 29.5 (interval [12.7, 17.5]), about 16 over the first 12 s but
  // 59 at 60 s, the excess all in the runs whose yaw error is large (NEES 150-220 at 60 s for
  // 0.8-1.1 rad, 12-19 below 0.2 rad) and in the velocity / tilt / accelerometer-bias
  // components. What the GPS does observe, position and velocity, stays consistent: that is
  // asserted here. (A magnetometer, or any yaw fix, removes the drift: see the mocap runs.)
  const Consistency c = monteCarlo(kHover, sensorPreset("onboard"), kRuns, 60.0, 6);
  report("onboard hover 60 s, position and velocity", c);
  EXPECT_GT(c.anees, c.lower);
  EXPECT_LT(c.anees, c.upper);
  EXPECT_GE(c.inside, 0.9);
}

TEST(EkfConsistency, OnboardFigureEightHasAChiSquareConsistentNees) {
  const Consistency c = monteCarlo(kFigureEight, sensorPreset("onboard"), kRuns, 24.0);
  report("onboard figure-eight 24 s", c);
  EXPECT_GT(c.anees, c.lower);
  EXPECT_LT(c.anees, c.upper);
  EXPECT_GE(c.inside, 0.9);
}

TEST(EkfAccuracy, TenfoldLessMocapNoiseGivesAClearlySmallerPositionError) {
  SensorSettings precise = sensorPreset("mocap");
  precise.position.noise *= 0.1;
  precise.attitude.noise_deg *= 0.1;
  const Consistency normal = monteCarlo(kFigureEight, sensorPreset("mocap"), 5, 12.0);
  const Consistency fine = monteCarlo(kFigureEight, precise, 5, 12.0);
  std::printf("[ RMSE     ] mocap %.5f m, mocap noise x0.1 %.5f m\n", normal.position_rmse,
              fine.position_rmse);
  EXPECT_LT(fine.position_rmse, 0.3 * normal.position_rmse);
}

TEST(EkfAccuracy, OnboardGpsPositionErrorIsFarAboveMotionCaptures) {
  const Consistency mocap = monteCarlo(kFigureEight, sensorPreset("mocap"), 5, 12.0);
  const Consistency onboard = monteCarlo(kFigureEight, sensorPreset("onboard"), 5, 12.0);
  std::printf("[ RMSE     ] mocap %.5f m, onboard %.4f m\n", mocap.position_rmse,
              onboard.position_rmse);
  EXPECT_GT(onboard.position_rmse, 20.0 * mocap.position_rmse);
  EXPECT_LT(onboard.position_rmse, 0.5);  // still better than one GPS fix (0.87 m in 3D)
}
