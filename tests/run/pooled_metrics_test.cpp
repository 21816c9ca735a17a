// A team's top-level figures pool its vehicles: lengths and energy add up, the RMS error is over
// every vehicle's tracked samples, extremes are the team's extremes; one vehicle is itself.
#include "run/pooled_metrics.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cosim {
namespace {

// A vehicle logged every 0.1 s for `samples` samples, arriving at `arrival` (or never: -1).
VehicleLog loggedVehicle(int samples, double arrival) {
  VehicleLog v;
  v.reached_goal = arrival >= 0.0;
  v.arrival_time = arrival;
  for (int k = 0; k < samples; ++k) v.samples.push_back(LogSample{.t = 0.1 * k});
  return v;
}

TEST(PooledMetrics, TrackedSamplesRunToArrivalOrTheWholeLog) {
  EXPECT_EQ(trackedSamples(loggedVehicle(10, 0.35)), 4u);  // t = 0, 0.1, 0.2, 0.3
  EXPECT_EQ(trackedSamples(loggedVehicle(10, -1.0)), 10u);
  EXPECT_EQ(trackedSamples(VehicleLog{}), 0u);
}

TEST(PooledMetrics, ATeamIsPooledOverItsMembersTrackedSamples) {
  RunLog log;
  log.vehicles = {loggedVehicle(10, 0.35), loggedVehicle(10, -1.0), loggedVehicle(10, 0.0)};
  std::vector<FlightMetrics> each(3);
  each[0] = {.reached_goal = true,
             .collisions = 1,
             .planned_length_m = 2.0,
             .flown_length_m = 2.5,
             .flight_time_s = 0.35,
             .error_reference = ErrorReference::Trajectory,
             .rmse_m = 0.3,
             .max_error_m = 0.5,
             .min_clearance_m = 0.4,
             .peak_thrust_fraction = 0.7,
             .saturated_fraction = 0.1,
             .energy_proxy = 10.0,
             .max_speed_mps = 1.0,
             .estimation_rmse_m = 0.02};
  each[1] = {.reached_goal = false,
             .collisions = 0,
             .planned_length_m = 4.0,
             .flown_length_m = 3.0,
             .flight_time_s = 0.9,
             .error_reference = ErrorReference::Trajectory,
             .rmse_m = 0.1,
             .max_error_m = 0.2,
             .min_clearance_m = 0.1,
             .peak_thrust_fraction = 0.9,
             .saturated_fraction = 0.3,
             .energy_proxy = 5.0,
             .max_speed_mps = 2.0,
             .estimation_rmse_m = 0.01};
  each[2].rmse_m = 100.0;  // not a member
  const FlightMetrics p = poolFlightMetrics(each, log, {0, 1});
  EXPECT_FALSE(p.reached_goal);
  EXPECT_EQ(p.collisions, 1);
  EXPECT_DOUBLE_EQ(p.planned_length_m, 6.0);
  EXPECT_DOUBLE_EQ(p.flown_length_m, 5.5);
  EXPECT_DOUBLE_EQ(p.energy_proxy, 15.0);
  EXPECT_DOUBLE_EQ(p.flight_time_s, 0.9);
  // 4 tracked samples at 0.3 m and 10 at 0.1 m: sqrt((4 * 0.09 + 10 * 0.01) / 14).
  EXPECT_NEAR(p.rmse_m, std::sqrt(0.46 / 14.0), 1e-12);
  EXPECT_NEAR(p.estimation_rmse_m, std::sqrt((10 * 4e-4 + 10 * 1e-4) / 20.0), 1e-12);
  EXPECT_NEAR(p.saturated_fraction, 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(p.max_error_m, 0.5);
  EXPECT_DOUBLE_EQ(p.peak_thrust_fraction, 0.9);
  EXPECT_DOUBLE_EQ(p.max_speed_mps, 2.0);
  EXPECT_DOUBLE_EQ(p.min_clearance_m, 0.1);
  EXPECT_EQ(p.error_reference, ErrorReference::Trajectory);
  each[1].error_reference = ErrorReference::PlannedPath;
  EXPECT_EQ(poolFlightMetrics(each, log, {0, 1}).error_reference, ErrorReference::Mixed);
}

TEST(PooledMetrics, OneVehicleIsItselfToTheLastBit) {
  RunLog log;
  log.vehicles = {loggedVehicle(7, 0.3), loggedVehicle(9, -1.0)};
  std::vector<FlightMetrics> each(2);
  each[1].rmse_m = 0.1234567890123;
  each[1].estimation_rmse_m = 0.0987654321;
  each[1].error_reference = ErrorReference::PlannedPath;
  const FlightMetrics p = poolFlightMetrics(each, log, {1});
  EXPECT_EQ(p.rmse_m, each[1].rmse_m);
  EXPECT_EQ(p.estimation_rmse_m, each[1].estimation_rmse_m);
  EXPECT_EQ(p.error_reference, ErrorReference::PlannedPath);
}

}  // namespace
}  // namespace cosim
