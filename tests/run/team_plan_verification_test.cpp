// A quadrotor team's plan flown before it is trusted (run/team_plan_verification.h): a team whose
// smoothed plan keeps 1.5 ellipsoids on paper but breaks in flight is caught by the first
// verification flight, repaired and flown clean; with too few rounds the run fails naming the
// pairs; and a team's trajectories are kept within team.max_thrust_fraction (run/team_thrust.h).
#include <gtest/gtest.h>

#include <string>

#include "run/run_pipeline.h"
#include "run/team_thrust.h"
#include "sim/downwash.h"
#include "tests/run/headless_run.h"
#include "tests/support/json_fields.h"

namespace cosim {
namespace {

// Two rows of three cf2, 0.5 m apart along x, swap ends of a 5 m room, one row climbing from
// 0.8 m to 1.8 m and the other descending: on the team grid each row passes 0.9 m under the
// other's hovering members (1.5 ellipsoids on paper), and their wakes push the lower ones into
// their neighbours (measured: 0.66 ellipsoids, b00 and b03 at 16.45 s).
std::string climbingRows(const std::string& team = "") {
  return "world:\n  bounds: {min: [0, 0, 0], max: [5, 3, 3]}\nvehicles:\n"
         "  - {name: b00, model: cf2, start: [0.75, 1.5, 0.8], goal: [4.25, 1.5, 1.8]}\n"
         "  - {name: b01, model: cf2, start: [1.25, 1.5, 0.8], goal: [3.75, 1.5, 1.8]}\n"
         "  - {name: b02, model: cf2, start: [1.75, 1.5, 0.8], goal: [3.25, 1.5, 1.8]}\n"
         "  - {name: b03, model: cf2, start: [4.25, 1.5, 1.8], goal: [0.75, 1.5, 0.8]}\n"
         "  - {name: b04, model: cf2, start: [3.75, 1.5, 1.8], goal: [1.25, 1.5, 0.8]}\n"
         "  - {name: b05, model: cf2, start: [3.25, 1.5, 1.8], goal: [1.75, 1.5, 0.8]}\n"
         "planner: {name: lacam, margin: 0.1}\n"
         "trajectory: {mode: minimum_snap, max_speed: 1.0, max_acceleration: 3.0}\n"
         "controller: {name: geometric}\n"
         "disturbances: {downwash: true}\n"
         "sim: {timestep: 0.001, control_rate: 500, max_time: 60, seed: 1}\n" +
         team;
}

RunRecord runTeam(const std::string& text, const std::string& name, std::string& metrics) {
  return test::runWithoutPictures(parseScenario(text, "verify_test.yaml"), name, metrics);
}

TEST(TeamPlanVerification, UnverifiedTheClimbingRowsEnterEachOthersEllipsoid) {
  std::string metrics;
  const RunRecord r = runTeam(climbingRows("team: {verify_rounds: 0}\n"), "verify-off", metrics);
  EXPECT_FALSE(r.planning.verification.ran);
  EXPECT_GE(test::jsonNumber(metrics, "planner_counters.planned_min_separation"), 1.5);
  EXPECT_LT(test::jsonNumber(metrics, "min_uav_separation_m"), 0.8);
  EXPECT_GT(test::jsonNumber(metrics, "downwash_violations"), 0);
}

TEST(TeamPlanVerification, TheFirstFlightFindsTheConflictAndTheRepairedPlanFliesClean) {
  std::string metrics;
  const RunRecord r = runTeam(climbingRows(), "verify-on", metrics);
  ASSERT_EQ(r.exitStatus(), 0) << r.message;
  const PlanVerificationReport& v = r.planning.verification;
  ASSERT_TRUE(v.ran);
  ASSERT_GE(v.rounds.size(), 2u);
  const VerificationRound& first = v.rounds.front();
  ASSERT_FALSE(first.conflicts.empty());
  EXPECT_LT(first.min_separation, 0.8);
  EXPECT_LT(first.conflicts.front().separation, 1.0);
  EXPECT_FALSE(first.repair.empty());
  EXPECT_TRUE(v.clean);
  EXPECT_TRUE(v.rounds.back().conflicts.empty());
  EXPECT_GE(v.rounds.back().min_separation, 1.0);
  // The run's own flight is the last verification flight.
  EXPECT_EQ(test::jsonNumber(metrics, "downwash_violations"), 0);
  EXPECT_DOUBLE_EQ(test::jsonNumber(metrics, "min_uav_separation_m"),
                   v.rounds.back().min_separation);
  EXPECT_EQ(test::jsonNumber(metrics, "uav_contacts"), 0);
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
  EXPECT_EQ(test::jsonNumber(metrics, "plan_verification.rounds_flown"),
            static_cast<double>(v.rounds.size()));
}

TEST(TeamPlanVerification, APlanStillBrokenAfterTheLastRoundFailsTheRunNamingThePairs) {
  std::string metrics;
  const RunRecord r = runTeam(climbingRows("team: {verify_rounds: 1}\n"), "verify-one", metrics);
  EXPECT_EQ(r.exitStatus(), 1);
  EXPECT_NE(r.message.find("still breaks in flight after 1 verification round"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("b00/b03 at "), std::string::npos) << r.message;
}

TEST(TeamThrust, AHoveringMemberAsksForItsWeightAndMoreUnderAWakeFromAbove) {
  QuadrotorParams cf2;
  cf2.rotor_xy = QuadrotorParams::xLayout(0.046);
  cf2.mass = 0.027;
  cf2.max_thrust = 0.149;  // N per rotor: thrust-to-weight 2.25 (models/cf2.xml)
  cf2.propeller_radius = 0.0231348;
  cf2.zero_thrust_inflow = 18.6;
  const auto hover = [](const Eigen::Vector3d& p) {
    PolynomialPiece piece;
    piece.duration = 1.0;
    piece.coefficients.row(0) = p.transpose();
    return PiecewisePolynomialTrajectory({piece});
  };
  const double alone = cf2.mass * cf2.gravity / (4.0 * cf2.max_thrust);  // 0.444
  TeamThrustPeak p = peakTeamThrust({hover({0, 0, 1})}, {cf2}, 0.1);
  EXPECT_NEAR(p.fraction, alone, 1e-9);
  // Another 0.9 m above: its four wakes, each at a quarter of its weight, slow the lower rotors.
  p = peakTeamThrust({hover({0, 0, 1}), hover({0, 0, 1.9})}, {cf2, cf2}, 0.1);
  const double u =
      2.0 * rotorWakeVelocity(0.25 * cf2.mass * cf2.gravity, cf2.propeller_radius, 0.9, 0.0);
  EXPECT_EQ(p.member, 0u);
  EXPECT_NEAR(p.fraction, alone / (1.0 - u / cf2.zero_thrust_inflow), 1e-9);
  EXPECT_GT(p.fraction, alone * 1.1);
}

TEST(TeamThrust, ATeamAskingMoreThanTheDeclaredFractionIsSlowedInPlanning) {
  // Two cf2 crossing at one height (no wake from above), allowed 3 m/s^2: a peak of
  // |a + g| / g x 0.444 = 0.46 of their thrust. Held to 0.45 the team is planned slower.
  const std::string crossing =
      "world:\n  bounds: {min: [0, 0, 0], max: [5, 3, 2.5]}\nvehicles:\n"
      "  - {name: a0, model: cf2, start: [0.8, 1.0, 1], goal: [4.2, 2.0, 1]}\n"
      "  - {name: b0, model: cf2, start: [4.2, 1.0, 1], goal: [0.8, 2.0, 1]}\n"
      "planner: {name: lacam, margin: 0.1}\n"
      "trajectory: {mode: minimum_snap, max_speed: 3.0, max_acceleration: 3.0}\n"
      "controller: {name: geometric}\ndisturbances: {downwash: true}\n"
      "sim: {timestep: 0.002, control_rate: 250, max_time: 0.1}\n";
  std::string metrics;
  runTeam(crossing + "team: {verify_rounds: 0}\n", "thrust-free", metrics);
  const double free_peak =
      test::jsonNumber(metrics, "planner_counters.planned_peak_thrust_fraction");
  EXPECT_GT(free_peak, 0.45);
  EXPECT_EQ(test::jsonNumber(metrics, "planner_counters.step_stretch"), 1.0);
  runTeam(crossing + "team: {verify_rounds: 0, max_thrust_fraction: 0.45}\n", "thrust-slow",
          metrics);
  EXPECT_GT(test::jsonNumber(metrics, "planner_counters.step_stretch"), 1.0);
  EXPECT_LE(test::jsonNumber(metrics, "planner_counters.planned_peak_thrust_fraction"), 0.45);
}

}  // namespace
}  // namespace cosim
