// The least-squares placement of a log on a run's clock and in its frame.
#include "experiments/compare/reference_alignment.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cosim::test {
namespace {

// A figure-eight-like path: no two instants look alike within a period.
Eigen::Vector3d eight(double t) {
  return {std::sin(0.8 * t), std::sin(1.6 * t) / 2, 1.0 + 0.1 * std::sin(0.4 * t)};
}

TEST(ReferenceAlignment, RecoversTimeOffsetAndTranslationOfAShiftedLog) {
  AlignmentProblem pr;
  for (int k = 0; k <= 2000; ++k) {  // 500 Hz over 4 s
    pr.s.push_back(0.002 * k);
    pr.target.push_back(eight(0.002 * k));
  }
  // The log at 100 Hz on a clock 3.217 s ahead, 1 s of margin either side, moved by d.
  const double tau = 3.217;
  const Eigen::Vector3d d(0.3, -0.2, 0.05);
  SampledPath log;
  for (int j = 0; j <= 600; ++j) {
    const double t = 2.0 + 0.01 * j;
    log.t.push_back(t);
    log.p.push_back(eight(t - tau) + d);
  }
  pr.log = &log;
  pr.fit_translation = true;
  double lo, hi;
  offsetRange(pr, lo, hi);
  EXPECT_DOUBLE_EQ(lo, 2.0);
  EXPECT_DOUBLE_EQ(hi, 4.0);
  const Alignment a = fitAlignment(pr);
  // Linear interpolation of a 100 Hz log costs about |p''| dt^2 / 8 = 1e-5 m: the fit is
  // exact to well under a millisecond and a millimetre.
  EXPECT_NEAR(a.time_offset, tau, 2e-4);
  EXPECT_NEAR((a.translation - d).norm(), 0.0, 1e-3);
  EXPECT_LT(a.rms, 1e-4);
  // Without the translation the same log fits badly: d stays in the residual.
  pr.fit_translation = false;
  const Alignment fixed_frame = fitAlignment(pr);
  EXPECT_EQ(fixed_frame.translation, Eigen::Vector3d::Zero());
  EXPECT_GT(fixed_frame.rms, 0.1);
}

}  // namespace
}  // namespace cosim::test
