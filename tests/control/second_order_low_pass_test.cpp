#include "control/second_order_low_pass.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

using namespace cosim;

namespace {

// The steady-state gain of the discrete filter for a sinusoid of `hz` sampled at `rate_hz`:
// the output's amplitude (after the transient) over the input's, from the sum of y sin and
// y cos over whole periods.
double gainAt(double cutoff_hz, double hz, double rate_hz) {
  SecondOrderLowPass<double> f(cutoff_hz);
  f.reset(0.0);
  const double dt = 1.0 / rate_hz;
  const int settle = static_cast<int>(20.0 * rate_hz / std::min(hz, cutoff_hz));
  const int periods = 50;
  const int n = static_cast<int>(std::round(periods * rate_hz / hz));
  double s = 0.0, c = 0.0;
  for (int k = 0; k < settle + n; ++k) {
    const double t = k * dt;
    const double y = f.update(std::sin(2 * M_PI * hz * t), dt);
    if (k >= settle) {
      // The output sample after the update belongs to the end of the step.
      s += y * std::sin(2 * M_PI * hz * (t + dt));
      c += y * std::cos(2 * M_PI * hz * (t + dt));
    }
  }
  return 2.0 * std::hypot(s, c) / n;
}

double dB(double gain) {
  return 20.0 * std::log10(gain);
}

}  // namespace

TEST(SecondOrderLowPass, PassesAConstantWithUnitGain) {
  SecondOrderLowPass<Eigen::Vector3d> f(30.0);
  f.reset(Eigen::Vector3d::Zero());
  const Eigen::Vector3d u(1.0, -2.0, 3.5);
  for (int k = 0; k < 1000; ++k) f.update(u, 0.002);
  EXPECT_LT((f.value() - u).norm(), 1e-12);
  EXPECT_LT(f.derivative().norm(), 1e-9);
}

TEST(SecondOrderLowPass, IsThreeDecibelsDownAtItsCutoff) {
  // At the controllers' 500 Hz and well oversampled: -3.01 dB (1/sqrt 2) within 0.1 dB.
  EXPECT_NEAR(dB(gainAt(30.0, 30.0, 500.0)), -3.01, 0.1);
  EXPECT_NEAR(dB(gainAt(30.0, 30.0, 20000.0)), -3.01, 0.01);
  // Flat below the cutoff (Butterworth: no resonant peak).
  EXPECT_NEAR(dB(gainAt(30.0, 3.0, 500.0)), 0.0, 0.01);
}

TEST(SecondOrderLowPass, FallsFortyDecibelsPerDecadeAboveItsCutoff) {
  // Second order: 1 / (f / f_c)^2 well above the cutoff, -40 dB at ten times it (a first-order
  // filter, also -3 dB at its cutoff, would give -20 dB).
  EXPECT_NEAR(dB(gainAt(30.0, 300.0, 20000.0)), -40.0, 0.1);
}

TEST(SecondOrderLowPass, ItsDerivativeIsTheSlopeOfARamp) {
  // A ramp of 2 units/s, held over each step: after the transient the output lags it by
  // 2 zeta / w_c seconds, and the derivative is the slope (at the end of each held step it
  // dips by the staircase's ripple, 1.2 % at 500 Hz, nothing at 10 kHz).
  const double cutoff = 30.0, w_c = 2 * M_PI * cutoff;
  for (double dt : {0.002, 0.0001}) {
    SecondOrderLowPass<double> f(cutoff);
    f.reset(0.0);
    double t = 0.0;
    for (int k = 0; k < static_cast<int>(1.0 / dt); ++k) {
      f.update(2.0 * t, dt);
      t += dt;
    }
    // The input held over the last step was 2 (t - dt): on average the filter has seen the
    // ramp delayed by dt / 2.
    EXPECT_NEAR(2.0 * (t - dt / 2) - f.value(), 2.0 * (2 * M_SQRT1_2 / w_c), 1e-5) << dt;
    EXPECT_NEAR(f.derivative(), 2.0, dt > 0.001 ? 0.03 : 1e-3) << dt;
  }
}

TEST(SecondOrderLowPass, StartsAtRestOnItsFirstInput) {
  SecondOrderLowPass<double> f(30.0);
  EXPECT_FALSE(f.initialised());
  EXPECT_EQ(f.update(9.81, 0.002), 9.81);
  EXPECT_EQ(f.derivative(), 0.0);
  EXPECT_EQ(f.update(9.81, 0.002), 9.81);
}
