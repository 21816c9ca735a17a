// The run pipeline as a library (what a Python front end calls): without an output folder it
// writes nothing and hands back everything the files would hold (metrics.json's object, the
// log, each vehicle's plan); it tells an observer its stages, lines and progress instead of
// printing; a team's top-level figures are the whole team's. The run resolves its defaults beside
// the scenario, which stays as loaded; how a run ended is an enum with one name for each end.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "run/metrics_json.h"
#include "run/record/run_setup.h"
#include "run/run_pipeline.h"
#include "sim/run_log_io.h"
#include "tests/support/json_fields.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

// Two cf2 fly straight lines of 2 m and 4 m side by side, through given waypoints.
const char* const kTwoCf2 =
    "world:\n  bounds: {min: [0, 0, 0], max: [6, 4, 2.5]}\nvehicles:\n"
    "  - {name: near, model: cf2, start: [1, 1, 1], goal: [3, 1, 1]}\n"
    "  - {name: far, model: cf2, start: [1, 3, 1], goal: [5, 3, 1]}\n"
    "trajectory: {mode: minimum_snap, max_speed: 1.0, max_acceleration: 1.0}\n"
    "controller: {name: geometric}\n"
    "sim: {timestep: 0.002, control_rate: 250, max_time: 20}\n";

// One omni base drives an L of 2 m + 2 m at 0.4 m/s.
const char* const kOneRobot =
    "world:\n  bounds: {min: [0, 0, 0], max: [4, 3, 1.5]}\nvehicles:\n"
    "  - {name: r0, model: omni_base, start: [0.5, 0.5, 0], waypoints: [[2.5, 0.5, 0]],\n"
    "     goal: [2.5, 2.5, 0]}\n"
    "trajectory: {max_speed: 0.4}\n"
    "sim: {timestep: 0.002, control_rate: 50, max_time: 30}\n";

// The current folder, for as long as this lives.
class WorkingFolder {
 public:
  explicit WorkingFolder(const std::filesystem::path& dir) : was_(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~WorkingFolder() { std::filesystem::current_path(was_); }
  WorkingFolder(const WorkingFolder&) = delete;
  WorkingFolder& operator=(const WorkingFolder&) = delete;

 private:
  std::filesystem::path was_;
};

// Runs with the current folder set to an empty scratch folder, which must stay empty.
RunRecord runInEmptyFolder(const std::string& text, const std::string& name,
                           const RunObserver& observer = {}) {
  Scenario s = parseScenario(text, name + ".yaml");
  const auto scratch = test::freshDir(name);
  std::filesystem::create_directories(scratch);
  RunRequest request;
  request.observer = observer;
  RunRecord r;
  {
    const WorkingFolder inside(scratch);
    r = executeRun(s, request);
  }
  EXPECT_TRUE(std::filesystem::is_empty(scratch)) << "a run without out_dir wrote a file";
  std::filesystem::remove_all(scratch);
  return r;
}

TEST(RunLibrary, WithoutAnOutputFolderWritesNothingAndReturnsWhatTheFilesWouldHold) {
  const RunRecord r = runInEmptyFolder(kTwoCf2, "library-flight");
  ASSERT_EQ(r.exitStatus(), 0) << r.message;
  const std::string metrics =
      runMetricsJson(parseScenario(kTwoCf2, "library-flight.yaml"), r).str();
  EXPECT_TRUE(test::jsonTrue(metrics, "reached_goal"));
  EXPECT_EQ(test::jsonNumber(metrics, "status"), 0);
  ASSERT_EQ(r.log.vehicles.size(), 2u);
  EXPECT_EQ(r.log.vehicles[1].name, "far");
  EXPECT_GT(r.log.vehicles[1].samples.size(), 250u);  // more than a second at 250 Hz
  const auto columns = timeseriesColumns(r.log, 1);
  EXPECT_EQ(columns[7].first, "x");
  EXPECT_NEAR(columns[7].second.back(), 5.0, 0.05);  // "far" ends at its goal
  ASSERT_EQ(r.plans.size(), 2u);
  ASSERT_EQ(r.plans[1].path.waypoints.size(), 2u);  // start and goal, given
  EXPECT_EQ(r.plans[1].path.waypoints.back(), Eigen::Vector3d(5, 3, 1));
}

TEST(RunLibrary, ATeamsTopLevelFiguresAreTheWholeTeams) {
  const RunRecord r = runInEmptyFolder(kTwoCf2, "library-team");
  ASSERT_EQ(r.exitStatus(), 0) << r.message;
  const std::string metrics = runMetricsJson(parseScenario(kTwoCf2, "library-team.yaml"), r).str();
  const FlightMetrics& near = r.metrics.vehicles[0];
  const FlightMetrics& far = r.metrics.vehicles[1];
  EXPECT_NEAR(test::jsonNumber(metrics, "planned_length_m"), 6.0, 1e-9);  // 2 m + 4 m
  EXPECT_NEAR(test::jsonNumber(metrics, "flown_length_m"), near.flown_length_m + far.flown_length_m,
              1e-6);
  EXPECT_NEAR(test::jsonNumber(metrics, "flight_time_s"), far.flight_time_s, 1e-9);  // longer
  EXPECT_NEAR(test::jsonNumber(metrics, "max_error_m"), std::max(near.max_error_m, far.max_error_m),
              1e-9);
  const double rmse = test::jsonNumber(metrics, "rmse_m");
  EXPECT_GT(rmse, std::min(near.rmse_m, far.rmse_m));
  EXPECT_LT(rmse, std::max(near.rmse_m, far.rmse_m));
}

TEST(RunLibrary, AnObserverHearsTheStagesLinesAndNoFilesStages) {
  std::vector<RunEvent> events;
  const RunRecord r = runInEmptyFolder(kOneRobot, "library-events",
                                       [&](const RunEvent& e) { events.push_back(e); });
  ASSERT_EQ(r.exitStatus(), 0) << r.message;
  std::vector<RunStage> stages;
  std::vector<std::string> lines;
  int progress = 0;
  for (const RunEvent& e : events) {
    if (e.kind == RunEventKind::Stage) stages.push_back(e.stage);
    if (e.kind == RunEventKind::Message) lines.push_back(e.text);
    if (e.kind != RunEventKind::Progress) continue;
    ++progress;
    EXPECT_EQ(e.stage, RunStage::Simulate);
    EXPECT_EQ(e.total, 11);  // the plan ends at 0.2 s + 4 m / 0.4 m/s = 10.2 s
  }
  EXPECT_EQ(stages, (std::vector<RunStage>{RunStage::Resolve, RunStage::Plan, RunStage::BuildPilots,
                                           RunStage::Simulate, RunStage::Evaluate}));
  EXPECT_EQ(lines, std::vector<std::string>{"driving 1 ground robot(s)"});
  EXPECT_GE(progress, 11);  // one per simulated second
}

TEST(RunLibrary, ARobotsPlanIsItsTimedPath) {
  const RunRecord r = runInEmptyFolder(kOneRobot, "library-robot");
  ASSERT_EQ(r.exitStatus(), 0) << r.message;
  ASSERT_EQ(r.plans.size(), 1u);
  const VehiclePlan& p = r.plans[0];
  ASSERT_EQ(p.point_times.size(), 3u);
  EXPECT_NEAR(p.point_times[0], 0.2, 1e-12);  // after settling on its wheels
  EXPECT_NEAR(p.point_times[1], 5.2, 1e-12);
  EXPECT_NEAR(p.point_times[2], 10.2, 1e-12);
  ASSERT_EQ(p.path.waypoints.size(), 3u);
  EXPECT_EQ(p.path.waypoints[1], Eigen::Vector3d(2.5, 0.5, 0));
  EXPECT_NEAR(r.metrics.schedule.planned_makespan_s, 10.2, 1e-9);
}

TEST(RunLibrary, MetricsJsonIsTheObjectWrittenToTheFolder) {
  Scenario s = parseScenario(kOneRobot, "library-files.yaml");
  RunRequest request;
  request.out_dir = test::freshDir("library-files");
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  const RunRecord r = executeRun(s, request);
  EXPECT_EQ(test::slurp(request.out_dir / "metrics.json"), runMetricsJson(s, r).str() + "\n");
  EXPECT_EQ(test::slurp(request.out_dir / "timeseries.csv"), timeseriesCsv(r.log));
  std::filesystem::remove_all(request.out_dir);
}

// Two cf2 swap places under a team planner, without a controller section.
const char* const kTeamWithoutController =
    "world:\n  bounds: {min: [0, 0, 0], max: [6, 4, 2.5]}\nvehicles:\n"
    "  - {name: a, model: cf2, start: [1, 2, 1], goal: [5, 2, 1]}\n"
    "  - {name: b, model: cf2, start: [5, 2, 1], goal: [1, 2, 1]}\n"
    "planner: {name: lacam}\n";

TEST(RunLibrary, ATeamsDefaultsAreResolvedBesideTheScenario) {
  const Scenario s = parseScenario(kTeamWithoutController, "library-team-defaults.yaml");
  const RunSetup setup = resolveRun(s, false);
  EXPECT_EQ(setup.quadrotor_planning, Planning::Team);
  EXPECT_EQ(setup.quadrotor_sections.controller.name, "indi");
  EXPECT_EQ(setup.quadrotor_sections.trajectory.mode, TrajectoryMode::MinimumSnap);
  EXPECT_EQ(&setup.primarySections(), &setup.quadrotor_sections);
  // The scenario keeps what its file said.
  EXPECT_EQ(s.motion.controller.name, "cascade");
  EXPECT_EQ(s.motion.trajectory.mode, TrajectoryMode::Waypoints);
}

TEST(RunLibrary, APointMassPlanKeepsNoMarginAndTheScenarioKeepsItsOwn) {
  const Scenario s = parseScenario(kTwoCf2, "library-point-mass.yaml");
  EXPECT_DOUBLE_EQ(resolveRun(s, true).quadrotor_sections.planner.margin, 0.0);
  EXPECT_DOUBLE_EQ(resolveRun(s, false).quadrotor_sections.planner.margin, 0.3);
  EXPECT_DOUBLE_EQ(s.motion.planner.margin, 0.3);
}

TEST(RunLibrary, EveryRunEndIsWrittenAndReadBackByOneName) {
  const std::vector<std::pair<RunEnd, std::string>> names = {
      {RunEnd::Running, "running"},     {RunEnd::Goal, "goal"},
      {RunEnd::MaxTime, "max_time"},    {RunEnd::Interrupted, "interrupted"},
      {RunEnd::Diverged, "diverged"},   {RunEnd::Unstable, "unstable"},
      {RunEnd::Saturated, "saturated"}, {RunEnd::GaveUp, "gave_up"},
      {RunEnd::NoPath, "no_path"}};
  for (const auto& [end, name] : names) {
    EXPECT_EQ(runEndName(end), name);
    EXPECT_EQ(runEndNamed(name), end) << name;
  }
  EXPECT_FALSE(runEndNamed("exploded").has_value());
}

TEST(RunLibrary, AStopBeforePlanningEndsTheRunAsInterrupted) {
  const Scenario s = parseScenario(kTwoCf2, "library-stopped.yaml");
  const std::atomic<bool> stop{true};
  RunRequest request;
  request.interrupt = &stop;
  std::vector<RunStage> stages;
  request.observer = [&stages](const RunEvent& e) {
    if (e.kind == RunEventKind::Stage) stages.push_back(e.stage);
  };
  const RunRecord r = executeRun(s, request);
  EXPECT_EQ(r.outcome, RunOutcome::Interrupted);
  EXPECT_EQ(r.exitStatus(), 1);
  EXPECT_TRUE(r.log.vehicles.empty());  // not flown
  EXPECT_EQ(stages, std::vector<RunStage>{RunStage::Resolve});
}

}  // namespace
}  // namespace cosim
