// The sampled reference's clamped cubic spline (control/sampled_reference.h) reproduces what it
// must: a cubic at rest at both ends (it is its own clamped spline) with every derivative,
// through unevenly spaced samples; two samples give the smoothstep; yaw turns the short way.
#include "control/sampled_reference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cosim {
namespace {

// p(t) = 3 t^2 - 2 t^3 on [0, 1]: p'(0) = p'(1) = 0, so the clamped spline through any samples
// of it is p itself.
double smoothstep(double t) {
  return 3 * t * t - 2 * t * t * t;
}

TEST(SampledReference, ReproducesACubicAtRestAtBothEndsWithItsDerivatives) {
  std::vector<ReferenceSample> samples;
  for (double t : {0.0, 0.1, 0.35, 0.5, 0.8, 1.0})
    samples.push_back({t, Eigen::Vector3d(smoothstep(t), 2.0 * smoothstep(t), 1.0), 0.0});
  const SampledReference ref(samples);
  EXPECT_DOUBLE_EQ(ref.duration(), 1.0);
  const FlatReference r = ref.at(0.6);
  EXPECT_NEAR(r.position.x(), 0.648, 1e-12);     // 3 (0.36) - 2 (0.216)
  EXPECT_NEAR(r.velocity.x(), 1.44, 1e-12);      // 6 t - 6 t^2
  EXPECT_NEAR(r.acceleration.x(), -1.2, 1e-12);  // 6 - 12 t
  EXPECT_NEAR(r.jerk.x(), -12.0, 1e-9);          // constant
  EXPECT_NEAR(r.velocity.y(), 2.88, 1e-12);
  EXPECT_NEAR(r.position.z(), 1.0, 1e-15);
  EXPECT_NEAR(r.velocity.z(), 0.0, 1e-15);
  EXPECT_EQ(r.snap.x(), 0.0);  // a cubic has none
}

TEST(SampledReference, TwoSamplesGiveTheSmoothstepBetweenThem) {
  // From x = 0 to x = 1 in 2 s: x = 3 (t/2)^2 - 2 (t/2)^3.
  const SampledReference ref(
      {{0.0, Eigen::Vector3d::Zero(), 0.0}, {2.0, Eigen::Vector3d(1.0, 0.0, 0.0), 0.0}});
  const FlatReference mid = ref.at(1.0);
  EXPECT_NEAR(mid.position.x(), 0.5, 1e-12);
  EXPECT_NEAR(mid.velocity.x(), 0.75, 1e-12);  // (6 s - 6 s^2) / 2 at s = 1/2
  EXPECT_NEAR(mid.acceleration.x(), 0.0, 1e-12);
  EXPECT_NEAR(mid.jerk.x(), -1.5, 1e-12);  // -12 / 2^3
  EXPECT_NEAR(ref.at(0.0).velocity.x(), 0.0, 1e-12);
}

TEST(SampledReference, TimesStartAtTheFirstSampleAndTimescaleApplies) {
  std::vector<ReferenceSample> samples;
  for (double t : {5.0, 5.25, 5.5, 6.0})
    samples.push_back({t, Eigen::Vector3d(smoothstep(t - 5.0), 0, 0), 0.0});
  const SampledReference ref(samples, {0.5, Eigen::Vector3d(0, 0, 1)});
  EXPECT_DOUBLE_EQ(ref.duration(), 0.5);
  const FlatReference r = ref.at(0.3);  // the samples' t = 5.6
  EXPECT_NEAR(r.position.x(), 0.648, 1e-12);
  EXPECT_NEAR(r.velocity.x(), 1.44 / 0.5, 1e-12);
  EXPECT_NEAR(r.acceleration.x(), -1.2 / 0.25, 1e-12);
  EXPECT_NEAR(r.position.z(), 1.0, 1e-15);
}

TEST(SampledReference, YawTurnsTheShortWayAcrossPi) {
  // 3.0 rad to -3.0 rad is 0.283 rad the short way (through pi), not 6 rad back.
  const SampledReference ref(
      {{0.0, Eigen::Vector3d::Zero(), 3.0}, {1.0, Eigen::Vector3d::Zero(), -3.0}});
  EXPECT_NEAR(ref.at(1.0).yaw, 2.0 * M_PI - 3.0, 1e-12);
  EXPECT_NEAR(ref.at(0.5).yaw, M_PI, 1e-12);
}

TEST(SampledReference, RefusesOneSampleAndTimesThatDoNotIncrease) {
  EXPECT_THROW(SampledReference({{0.0, Eigen::Vector3d::Zero(), 0.0}}), std::invalid_argument);
  EXPECT_THROW(
      SampledReference({{0.0, Eigen::Vector3d::Zero(), 0.0}, {0.0, Eigen::Vector3d::Ones(), 0.0}}),
      std::invalid_argument);
}

}  // namespace
}  // namespace cosim
