// The least-squares placement of a log on a run's clock and in its frame.
#include "experiments/compare/reference_alignment.h"

#include <gtest/gtest.h>

#include <atomic>
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
  pr.translation = FittedTranslation::XYZ;
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
  pr.translation = FittedTranslation::None;
  const Alignment fixed_frame = fitAlignment(pr);
  EXPECT_EQ(fixed_frame.translation, Eigen::Vector3d::Zero());
  EXPECT_GT(fixed_frame.rms, 0.1);
}

// The window of the tests: 4 s at 500 Hz against eight().
AlignmentProblem eightWindow() {
  AlignmentProblem pr;
  for (int k = 0; k <= 2000; ++k) {
    pr.s.push_back(0.002 * k);
    pr.target.push_back(eight(0.002 * k));
  }
  return pr;
}

// eight() at 100 Hz on a clock `tau` ahead, from log time `from` for `seconds`, moved by d.
SampledPath eightLog(double tau, double from, double seconds, const Eigen::Vector3d& d) {
  SampledPath log;
  for (int j = 0; j <= static_cast<int>(std::lround(seconds * 100)); ++j) {
    const double t = from + 0.01 * j;
    log.t.push_back(t);
    log.p.push_back(eight(t - tau) + d);
  }
  return log;
}

TEST(ReferenceAlignment, AHorizontalTranslationLeavesTheHeightOffsetInTheResidual) {
  AlignmentProblem pr = eightWindow();
  const SampledPath log = eightLog(3.217, 2.0, 6.0, Eigen::Vector3d(0.3, -0.2, 0.05));
  pr.log = &log;
  pr.translation = FittedTranslation::XY;
  const Alignment a = fitAlignment(pr);
  EXPECT_NEAR(a.translation.x(), 0.3, 1e-3);
  EXPECT_NEAR(a.translation.y(), -0.2, 1e-3);
  EXPECT_EQ(a.translation.z(), 0.0);
  EXPECT_NEAR(a.rms, 0.05, 1e-3);  // the height, not fitted
  EXPECT_NEAR(a.time_offset, 3.217, 2e-3);
}

TEST(ReferenceAlignment, ASearchAtEpochSecondsEndsAndPlacesTheLog) {
  // At 8.6e9 s a double resolves 2e-6 s, coarser than the 1e-6 s bracket the search aims at: it
  // stops where the offsets' precision ends instead of spinning for ever.
  AlignmentProblem pr = eightWindow();
  const double tau = 8.6e9 + 3.217;
  const SampledPath log = eightLog(tau, 8.6e9 + 2.0, 6.0, Eigen::Vector3d::Zero());
  pr.log = &log;
  const Alignment a = fitAlignment(pr);
  EXPECT_NEAR(a.time_offset - 8.6e9, 3.217, 1e-3);
  EXPECT_LT(a.rms, 1e-3);
}

TEST(ReferenceAlignment, FarSamplesAroundAFlightAreNotSearchedAndFarApartSamplesAreNothing) {
  AlignmentProblem pr = eightWindow();
  // The flight (6 s at 100 Hz) with one sample 1e7 s before and one 1e7 s after it: a scan of
  // the whole 2e7 s in 20000 steps would step 1000 s at a time past the flight.
  SampledPath log = eightLog(3.217, 2.0, 6.0, Eigen::Vector3d::Zero());
  log.t.insert(log.t.begin(), -1e7);
  log.p.insert(log.p.begin(), eight(0.0));
  log.t.push_back(1e7);
  log.p.push_back(eight(0.0));
  pr.log = &log;
  const std::vector<OffsetInterval> searched = searchedOffsets(pr);
  // Searched: where the 4 s window holds ten of the flight's samples (2.00 .. 8.00 s), from
  // ending on its tenth (2.09 - 4) to starting on its tenth from last (7.91).
  ASSERT_EQ(searched.size(), 1u);
  EXPECT_NEAR(searched[0].lo, -1.91, 1e-9);
  EXPECT_NEAR(searched[0].hi, 7.91, 1e-9);
  EXPECT_NEAR(fitAlignment(pr).time_offset, 3.217, 2e-4);
  // Samples 1e6 s apart: no placement of the 4 s window holds ten of them.
  SampledPath sparse;
  for (int j = 0; j < 20; ++j) {
    sparse.t.push_back(1e6 * j);
    sparse.p.push_back(eight(j));
  }
  pr.log = &sparse;
  EXPECT_TRUE(searchedOffsets(pr).empty());
  EXPECT_THROW(fitAlignment(pr), std::invalid_argument);
}

TEST(ReferenceAlignment, AStopRequestEndsTheFit) {
  AlignmentProblem pr = eightWindow();
  const SampledPath log = eightLog(3.217, 2.0, 6.0, Eigen::Vector3d::Zero());
  pr.log = &log;
  std::atomic<bool> stop{true};
  EXPECT_THROW(fitAlignment(pr, StopToken::untimed(&stop)), AlignmentInterrupted);
  stop = false;
  EXPECT_NEAR(fitAlignment(pr, StopToken::untimed(&stop)).time_offset, 3.217, 2e-4);
}

}  // namespace
}  // namespace cosim::test
