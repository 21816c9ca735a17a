// Per-axis lag and amplitude ratio of a flight against its reference.
#include "experiments/compare/axis_tracking.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cosim::test {
namespace {

// A flat figure-eight-like reference: x and y move, z stays at 1 m.
Eigen::Vector3d flatEight(double t) {
  return {std::sin(0.8 * t), std::sin(1.6 * t) / 2, 1.0};
}

TEST(AxisTracking, RecoversEachAxisLagAndGainAndLeavesAStillAxisUndefined) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> r;
  for (int k = 0; k <= 4000; ++k) {  // 500 Hz over 8 s
    t.push_back(0.002 * k);
    r.push_back(flatEight(0.002 * k));
  }
  // The flight: x 120 ms late at 90 % of the reference's size, y 40 ms late at full size and
  // 5 cm aside (an offset is not a lag), z 2 cm high; at 100 Hz from 1 s before to 1 s after.
  SampledPath flight;
  for (int j = 0; j <= 1000; ++j) {
    const double s = -1.0 + 0.01 * j;
    flight.t.push_back(s);
    flight.p.emplace_back(0.9 * flatEight(s - 0.12).x(), flatEight(s - 0.04).y() + 0.05, 1.02);
  }
  const AxisTracking a = axisTracking(t, r, flight);
  EXPECT_NEAR(a.lag_s.x(), 0.12, 1e-3);
  EXPECT_NEAR(a.lag_s.y(), 0.04, 1e-3);
  EXPECT_NEAR(a.amplitude_ratio.x(), 0.9, 2e-3);
  EXPECT_NEAR(a.amplitude_ratio.y(), 1.0, 2e-3);
  EXPECT_TRUE(std::isnan(a.lag_s.z()));
  EXPECT_TRUE(std::isnan(a.amplitude_ratio.z()));
}

}  // namespace
}  // namespace cosim::test
