// The figure-eight reference of the controller study: its derivatives are those of its
// position, it reaches the peak speed it was asked for, and it ends at rest where it began.
#include "control/figure_eight_reference.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cosim;

namespace {

FigureEightShape shape() {
  FigureEightShape s;
  s.centre = {10, 6, 3};
  s.amplitude = 8.0;
  s.peak_speed = 6.0;
  s.laps = 2;
  s.ramp = 3.0;
  return s;
}

}  // namespace

TEST(FigureEightReference, EachDerivativeIsTheCentralDifferenceOfTheOneBelow) {
  FigureEightReference ref(shape());
  const VehicleState none;
  const double h = 1e-4;
  // In the ramp up, the cruise and the ramp down.
  for (double t : {1.3, 2.9, 7.0, ref.duration() - 2.2, ref.duration() - 0.4}) {
    const FlatReference a = ref.reference(t - h, none), b = ref.reference(t + h, none),
                        c = ref.reference(t, none);
    EXPECT_LT(((b.position - a.position) / (2 * h) - c.velocity).norm(), 1e-5) << t;
    EXPECT_LT(((b.velocity - a.velocity) / (2 * h) - c.acceleration).norm(), 1e-5) << t;
    EXPECT_LT(((b.acceleration - a.acceleration) / (2 * h) - c.jerk).norm(), 1e-4) << t;
    EXPECT_LT(((b.jerk - a.jerk) / (2 * h) - c.snap).norm(), 1e-3) << t;
  }
}

TEST(FigureEightReference, ReachesThePeakSpeedAndEndsAtRestAtTheCentre) {
  FigureEightReference ref(shape());
  const VehicleState none;
  double peak = 0.0;
  for (double t = 0.0; t <= ref.duration(); t += 0.001)
    peak = std::max(peak, ref.reference(t, none).velocity.norm());
  EXPECT_NEAR(peak, 6.0, 0.01);
  const FlatReference start = ref.reference(0.0, none);
  EXPECT_LT((start.position - shape().centre).norm(), 1e-12);
  EXPECT_FALSE(ref.atFinalSetpoint());
  const FlatReference end = ref.reference(ref.duration() + 1.0, none);
  EXPECT_TRUE(ref.atFinalSetpoint());
  EXPECT_LT((end.position - shape().centre).norm(), 1e-9);
  EXPECT_LT(end.velocity.norm(), 1e-12);
  // Two whole laps: the phase ends at 4 pi.
  EXPECT_NEAR(ref.phase(ref.duration()).phi, 4.0 * M_PI, 1e-9);
}

TEST(FigureEightReference, RefusesRampsLongerThanTheLaps) {
  FigureEightShape s = shape();
  s.laps = 1;
  s.ramp = 60.0;  // each ramp alone turns w T / 2 = 0.53 * 60 / 2 rad, more than 2 pi together
  EXPECT_THROW(FigureEightReference{s}, std::invalid_argument);
}
