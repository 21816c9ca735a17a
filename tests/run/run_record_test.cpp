// The record of a run (run/record/run_record.h): each vehicle's kind and error reference resolved
// once from the scenario, the typed metrics the evaluation measured against them, the per-sample
// tracking errors the pictures colour by, and metrics.json written from the record.
#include "run/record/run_record.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run/metrics_json.h"
#include "run/record/run_setup.h"
#include "run/run_pipeline.h"
#include "sim/scenario.h"
#include "tests/run/robot_and_uav_scenario.h"
#include "tests/support/json_fields.h"

namespace cosim {
namespace {

const std::string& kRobotAndUav = test::kRobotAndUavScenario;

// Two quadrotors following given waypoints, or a team planner's plan.
std::string twoQuadrotors(const std::string& planner) {
  return "world:\n  bounds: {min: [0, 0, 0], max: [6, 6, 3]}\nvehicles:\n"
         "  - {name: a, model: cf2, start: [1, 1, 1], goal: [5, 1, 1]}\n"
         "  - {name: b, model: cf2, start: [1, 5, 1], goal: [5, 5, 1]}\n" +
         planner + "trajectory: {mode: waypoints}\n";
}

TEST(RunRecord, ARobotIsMeasuredAgainstItsTimedPlanAndAQuadrotorOverItAgainstItsTrajectory) {
  const RunSetup setup = resolveRun(parseScenario(kRobotAndUav, "mixed.yaml"), false);
  ASSERT_EQ(setup.vehicles.size(), 2u);
  EXPECT_EQ(setup.vehicles[0].kind, VehicleKind::GroundRobot);
  EXPECT_EQ(setup.vehicles[0].error_reference, ErrorReference::TimedPlan);
  EXPECT_EQ(setup.vehicles[1].kind, VehicleKind::Quadrotor);
  // The `aerial` trajectory mode, not the top-level (the robots') waypoints.
  EXPECT_EQ(setup.vehicles[1].error_reference, ErrorReference::Trajectory);
  EXPECT_EQ(&setup.sectionsOf(1), &setup.quadrotor_sections);
  EXPECT_EQ(&setup.sectionsOf(0), &setup.robot_sections);
}

TEST(RunRecord, WaypointsAreMeasuredAgainstThePathUnlessATeamFliesTrajectories) {
  const RunSetup alone = resolveRun(parseScenario(twoQuadrotors(""), "alone.yaml"), false);
  EXPECT_EQ(alone.vehicles[0].error_reference, ErrorReference::PlannedPath);
  EXPECT_EQ(alone.vehicles[1].error_reference, ErrorReference::PlannedPath);
  // A team planner's quadrotors fly minimum-snap trajectories whatever the file said.
  const RunSetup team = resolveRun(
      parseScenario(twoQuadrotors("planner: {name: cbs, resolution: 0.5}\n"), "team.yaml"), false);
  EXPECT_EQ(team.vehicles[0].planning, Planning::Team);
  EXPECT_EQ(team.vehicles[1].error_reference, ErrorReference::Trajectory);
}

TEST(RunRecord, TheEvaluationMeasuresEachVehicleAgainstItsOwnReferenceAndWritesThatToMetricsJson) {
  const Scenario s = parseScenario(kRobotAndUav, "mixed.yaml");
  const RunRecord r = executeRun(s, RunRequest());
  ASSERT_EQ(r.outcome, RunOutcome::Succeeded) << r.message;
  ASSERT_EQ(r.metrics.vehicles.size(), 2u);
  EXPECT_EQ(r.metrics.vehicles[0].error_reference, ErrorReference::TimedPlan);
  EXPECT_EQ(r.metrics.vehicles[1].error_reference, ErrorReference::Trajectory);
  EXPECT_EQ(r.metrics.team.error_reference, ErrorReference::TimedPlan);  // the robots' pool
  // The series the pictures colour by: one error per logged sample, whose RMS up to the arrival
  // is the vehicle's rmse_m.
  const VehicleLog& uav = r.log.vehicles[1];
  const std::vector<double>& e = r.metrics.tracking_errors[1];
  ASSERT_EQ(e.size(), uav.samples.size());
  double sum_sq = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (uav.samples[k].t > trackingEnd(uav)) continue;
    sum_sq += e[k] * e[k];
    ++n;
  }
  ASSERT_GT(n, 100u);
  EXPECT_NEAR(std::sqrt(sum_sq / static_cast<double>(n)), r.metrics.vehicles[1].rmse_m, 1e-12);
  EXPECT_GT(r.metrics.vehicles[1].rmse_m, 0.0);
  const std::string json = runMetricsJson(s, r).str();
  // The headline's (the robots') first, then the quadrotor's entry.
  const auto headline = json.find("\"error_reference\": \"timed_plan\"");
  EXPECT_NE(headline, std::string::npos) << json;
  EXPECT_LT(headline, json.find("\"vehicles\""));
  EXPECT_NE(json.find("\"error_reference\": \"trajectory\""), std::string::npos) << json;
  EXPECT_EQ(test::jsonNumber(json, "status"), 0);
  EXPECT_EQ(runTitle(s, r), "cosim run: mixed (given waypoints, cascade controller)");
}

}  // namespace
}  // namespace cosim
