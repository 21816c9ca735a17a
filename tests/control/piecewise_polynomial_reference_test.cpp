// A piecewise-polynomial reference (control/piecewise_polynomial_reference.h) against values
// worked by hand: inside a piece and at a piece boundary, every derivative; the timescale
// scaling each derivative by 1/timescale^k; the relative offset; the held ends.
#include "control/piecewise_polynomial_reference.h"

#include <gtest/gtest.h>

namespace cosim {
namespace {

// Piece 0 (2 s): x = 1 + tau^2, y = tau^4, z = 0.5 tau^7, yaw = 0.1 tau^3.
// Piece 1 (1 s): x = 5 + 4 tau (x and its velocity continue piece 0's at tau = 2: 5 and 4),
//                y = 16, z = 64, yaw = 0.8.
std::vector<ReferencePiece> twoPieces() {
  ReferencePiece a, b;
  a.duration = 2.0;
  a.coefficients(0, 0) = 1.0;
  a.coefficients(2, 0) = 1.0;
  a.coefficients(4, 1) = 1.0;
  a.coefficients(7, 2) = 0.5;
  a.coefficients(3, 3) = 0.1;
  b.duration = 1.0;
  b.coefficients(0, 0) = 5.0;
  b.coefficients(1, 0) = 4.0;
  b.coefficients(0, 1) = 16.0;
  b.coefficients(0, 2) = 64.0;
  b.coefficients(0, 3) = 0.8;
  return {a, b};
}

TEST(PiecewisePolynomialReference, InsideAPieceEveryDerivativeIsThePolynomials) {
  const PiecewisePolynomialReference ref(twoPieces());
  EXPECT_DOUBLE_EQ(ref.duration(), 3.0);
  const FlatReference r = ref.at(1.0);  // tau = 1 in piece 0
  // x = 1 + tau^2: 2, 2 tau = 2, 2, 0, 0
  EXPECT_DOUBLE_EQ(r.position.x(), 2.0);
  EXPECT_DOUBLE_EQ(r.velocity.x(), 2.0);
  EXPECT_DOUBLE_EQ(r.acceleration.x(), 2.0);
  EXPECT_DOUBLE_EQ(r.jerk.x(), 0.0);
  // y = tau^4: 1, 4, 12, 24, 24
  EXPECT_DOUBLE_EQ(r.position.y(), 1.0);
  EXPECT_DOUBLE_EQ(r.velocity.y(), 4.0);
  EXPECT_DOUBLE_EQ(r.acceleration.y(), 12.0);
  EXPECT_DOUBLE_EQ(r.jerk.y(), 24.0);
  EXPECT_DOUBLE_EQ(r.snap.y(), 24.0);
  // z = 0.5 tau^7: 0.5, 3.5, 21, 105, 420
  EXPECT_DOUBLE_EQ(r.position.z(), 0.5);
  EXPECT_DOUBLE_EQ(r.velocity.z(), 3.5);
  EXPECT_DOUBLE_EQ(r.acceleration.z(), 21.0);
  EXPECT_DOUBLE_EQ(r.jerk.z(), 105.0);
  EXPECT_DOUBLE_EQ(r.snap.z(), 420.0);
  // yaw = 0.1 tau^3: 0.1, 0.3, 0.6
  EXPECT_DOUBLE_EQ(r.yaw, 0.1);
  EXPECT_DOUBLE_EQ(r.yaw_rate, 0.3);
  EXPECT_DOUBLE_EQ(r.yaw_acceleration, 0.6);
}

TEST(PiecewisePolynomialReference, AtABoundaryTheNextPieceStartsAndJustBeforeItThePreviousEnds) {
  const PiecewisePolynomialReference ref(twoPieces());
  const FlatReference at = ref.at(2.0);  // piece 1 at tau = 0
  EXPECT_DOUBLE_EQ(at.position.x(), 5.0);
  EXPECT_DOUBLE_EQ(at.velocity.x(), 4.0);
  EXPECT_DOUBLE_EQ(at.acceleration.x(), 0.0);  // piece 1 is a line
  EXPECT_DOUBLE_EQ(at.position.z(), 64.0);
  EXPECT_DOUBLE_EQ(at.velocity.z(), 0.0);
  const FlatReference before = ref.at(2.0 - 1e-9);  // piece 0 at tau -> 2: z' = 3.5 tau^6 = 224
  EXPECT_NEAR(before.position.x(), 5.0, 1e-8);
  EXPECT_NEAR(before.velocity.x(), 4.0, 1e-8);
  EXPECT_NEAR(before.acceleration.x(), 2.0, 1e-8);
  EXPECT_NEAR(before.velocity.z(), 224.0, 1e-5);
  EXPECT_NEAR(before.yaw_rate, 1.2, 1e-8);  // 0.3 tau^2
}

TEST(PiecewisePolynomialReference, TimescaleStretchesTimeAndScalesEachDerivative) {
  // Half the timescale: twice as fast; at t = 0.5 the pieces are at tau = 1.
  const PiecewisePolynomialReference ref(twoPieces(), {0.5, Eigen::Vector3d::Zero()});
  EXPECT_DOUBLE_EQ(ref.duration(), 1.5);
  const FlatReference r = ref.at(0.5);
  EXPECT_DOUBLE_EQ(r.position.y(), 1.0);              // positions unchanged
  EXPECT_DOUBLE_EQ(r.velocity.y(), 4.0 / 0.5);        // 1/s
  EXPECT_DOUBLE_EQ(r.acceleration.y(), 12.0 / 0.25);  // 1/s^2
  EXPECT_DOUBLE_EQ(r.jerk.y(), 24.0 / 0.125);         // 1/s^3
  EXPECT_DOUBLE_EQ(r.snap.y(), 24.0 / 0.0625);        // 1/s^4
  EXPECT_DOUBLE_EQ(r.snap.z(), 420.0 / 0.0625);
  EXPECT_DOUBLE_EQ(r.yaw, 0.1);
  EXPECT_DOUBLE_EQ(r.yaw_rate, 0.3 / 0.5);
  EXPECT_DOUBLE_EQ(r.yaw_acceleration, 0.6 / 0.25);
  // Twice the timescale: half as fast, t = 2 is tau = 1.
  const FlatReference slow = ref.placed({2.0, Eigen::Vector3d::Zero()}).at(2.0);
  EXPECT_DOUBLE_EQ(slow.velocity.z(), 3.5 / 2.0);
  EXPECT_DOUBLE_EQ(slow.jerk.z(), 105.0 / 8.0);
}

TEST(PiecewisePolynomialReference, OffsetMovesEveryPointAndNoDerivative) {
  const Eigen::Vector3d start(1.0, -2.0, 0.75);
  const PiecewisePolynomialReference ref(twoPieces(), {1.0, start});
  const FlatReference r = ref.at(1.0);
  EXPECT_DOUBLE_EQ(r.position.x(), 2.0 + 1.0);
  EXPECT_DOUBLE_EQ(r.position.y(), 1.0 - 2.0);
  EXPECT_DOUBLE_EQ(r.position.z(), 0.5 + 0.75);
  EXPECT_DOUBLE_EQ(r.velocity.z(), 3.5);
  EXPECT_DOUBLE_EQ(r.yaw, 0.1);
}

TEST(PiecewisePolynomialReference, HoldsTheFirstPointBeforeAndTheLastAfterAtRest) {
  PiecewisePolynomialReference ref(twoPieces());
  const FlatReference before = ref.at(-1.0);
  EXPECT_DOUBLE_EQ(before.position.x(), 1.0);
  EXPECT_TRUE(before.velocity.isZero());
  const FlatReference end = ref.reference(2.9, VehicleState{});
  EXPECT_FALSE(ref.atFinalSetpoint());
  EXPECT_NEAR(end.position.x(), 5.0 + 4.0 * 0.9, 1e-12);
  const FlatReference after = ref.reference(10.0, VehicleState{});
  EXPECT_TRUE(ref.atFinalSetpoint());
  EXPECT_DOUBLE_EQ(after.position.x(), 9.0);  // piece 1 at its end
  EXPECT_DOUBLE_EQ(after.position.z(), 64.0);
  EXPECT_DOUBLE_EQ(after.yaw, 0.8);
  EXPECT_TRUE(after.velocity.isZero());
  EXPECT_TRUE(after.acceleration.isZero());
  EXPECT_EQ(after.yaw_rate, 0.0);
}

TEST(PiecewisePolynomialReference, SampledPathRunsFromTheFirstToTheLastPoint) {
  const PiecewisePolynomialReference ref(twoPieces(), {1.0, Eigen::Vector3d(0, 0, 1)});
  const auto path = ref.sampledPath(7, 0.01);
  ASSERT_EQ(path.size(), 7u);  // capped: 6 intervals of 0.5 s
  EXPECT_DOUBLE_EQ(path.front().x(), 1.0);
  EXPECT_DOUBLE_EQ(path[2].x(), 2.0);  // t = 1
  EXPECT_DOUBLE_EQ(path.back().x(), 9.0);
  EXPECT_DOUBLE_EQ(path.back().z(), 65.0);
  EXPECT_EQ(ref.sampledPath(1000, 1.0).size(), 4u);  // one point a second
}

TEST(PiecewisePolynomialReference, RefusesNoPiecesZeroDurationsAndBadTimescales) {
  EXPECT_THROW(PiecewisePolynomialReference({}), std::invalid_argument);
  std::vector<ReferencePiece> zero = twoPieces();
  zero[1].duration = 0.0;
  EXPECT_THROW(PiecewisePolynomialReference{zero}, std::invalid_argument);
  EXPECT_THROW(PiecewisePolynomialReference(twoPieces(), {0.0, Eigen::Vector3d::Zero()}),
               std::invalid_argument);
  EXPECT_THROW(PiecewisePolynomialReference(twoPieces(), {-1.0, Eigen::Vector3d::Zero()}),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosim
