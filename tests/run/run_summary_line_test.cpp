// The console line of a finished run, from its record: the top-level (pooled) figures, whose they
// are, and what the error was measured against; the last line names the pages to open. The
// expected lines are those the console printed from metrics.json before the record existed.
#include "run/run_summary_line.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>

#include "tests/support/test_files.h"

using namespace cosim;

namespace {

// A two-quadrotor team whose first member's figures differ from the team's pooled ones.
RunRecord twoVehicleTeam() {
  RunRecord r;
  r.setup.quadrotors = {0, 1};
  r.setup.vehicles.resize(2);
  r.log.vehicles.resize(2);
  RunMetrics& m = r.metrics;
  m.reached_goal = true;
  m.collisions = 0;
  m.min_clearance_m = 0.141;
  m.sim_speed_x = 3.5;
  m.team.flight_time_s = 20.5;
  m.team.rmse_m = 0.0173;
  m.team.max_error_m = 0.137;
  m.team.error_reference = ErrorReference::Trajectory;
  m.vehicles.resize(2);
  m.vehicles[0].rmse_m = 0.0203;
  return r;
}

// Robots (and, with `uavs`, quadrotors over them) measured against their timed plans.
RunRecord groundRun(std::size_t robots, std::size_t uavs) {
  RunRecord r = twoVehicleTeam();
  r.setup = RunSetup();
  for (std::size_t k = 0; k < robots; ++k) r.setup.robots.push_back(k);
  for (std::size_t k = 0; k < uavs; ++k) r.setup.quadrotors.push_back(robots + k);
  r.log.vehicles.resize(robots + uavs);
  r.metrics.team.error_reference = ErrorReference::TimedPlan;
  return r;
}

}  // namespace

TEST(RunSummaryLine, ATeamPrintsItsPooledFiguresAndSaysSo) {
  const std::string line = runSummaryLine(twoVehicleTeam());
  EXPECT_EQ(line,
            "team of 2 (pooled): reached_goal yes, collisions 0, flight 20.5 s, rmse 0.0173 m "
            "(against the reference trajectory), max error 0.137 m, min clearance 0.141 m, "
            "3.5x real time");
  EXPECT_EQ(line.find("0.0203"), std::string::npos);  // not the first vehicle's
}

TEST(RunSummaryLine, AGroundTeamNamesItsTimedPlan) {
  const std::string line = runSummaryLine(groundRun(2, 0));
  EXPECT_EQ(line,
            "team of 2 (pooled): reached_goal yes, collisions 0, flight 20.5 s, rmse 0.0173 m "
            "(against the timed plan), max error 0.137 m, min clearance 0.141 m, 3.5x real time");
}

TEST(RunSummaryLine, RobotsWithQuadrotorsPrintBothGroups) {
  RunRecord r = groundRun(1, 1);
  r.metrics.uavs.rmse_m = 0.031;
  r.metrics.uavs.max_error_m = 0.09;
  EXPECT_EQ(runSummaryLine(r),
            "robots (1, pooled): reached_goal yes, collisions 0, flight 20.5 s, rmse 0.0173 m "
            "(against the timed plan), max error 0.137 m, min clearance 0.141 m; quadrotors (1, "
            "pooled): rmse 0.031 m, max error 0.09 m, 3.5x real time");
}

TEST(RunSummaryLine, ASingleVehicleLineHasNoTeamPrefixAndNoClearanceWithoutObstacles) {
  RunRecord r = twoVehicleTeam();
  r.log.vehicles.resize(1);
  r.metrics.team.error_reference = ErrorReference::PlannedPath;
  r.metrics.reached_goal = false;
  r.metrics.collisions = 2;
  // No obstacle to measure a clearance to: metrics.json writes null, the console says so.
  r.metrics.min_clearance_m = std::numeric_limits<double>::infinity();
  EXPECT_EQ(runSummaryLine(r),
            "reached_goal no, collisions 2, flight 20.5 s, rmse 0.0173 m (against the planned "
            "path), max error 0.137 m, min clearance none (no obstacles), 3.5x real time");
}

TEST(RunSummaryLine, ANegativeClearanceSaysItIsTheBoundingSphereAndWhetherAnythingTouched) {
  RunRecord r = twoVehicleTeam();
  r.log.vehicles.resize(1);
  r.metrics.min_clearance_m = -0.0333;
  EXPECT_NE(runSummaryLine(r).find("min clearance -0.0333 m (bounding sphere into an obstacle, no "
                                   "part touched it), "),
            std::string::npos)
      << runSummaryLine(r);
  r.metrics.collisions = 1;
  EXPECT_NE(runSummaryLine(r).find("min clearance -0.0333 m (bounding sphere into an obstacle), "),
            std::string::npos)
      << runSummaryLine(r);
}

TEST(RunSummaryLine, APoolOfDifferentReferencesSaysEachVehicles) {
  EXPECT_EQ(errorReferenceWords(ErrorReference::Mixed), "each vehicle's reference");
}

TEST(RunSummaryLine, TheLastLineNamesIndexAndViewerWhenPresent) {
  const auto dir = cosim::test::makeFreshDir("run-pages-line");
  EXPECT_EQ(runPagesLine(dir), "results in " + dir.string());
  std::ofstream(dir / "index.html") << "<html></html>";
  EXPECT_EQ(runPagesLine(dir), "open " + (dir / "index.html").string());
  std::ofstream(dir / "viewer.html") << "<html></html>";
  EXPECT_EQ(runPagesLine(dir),
            "open " + (dir / "index.html").string() + " or " + (dir / "viewer.html").string());
  std::filesystem::remove_all(dir);
}
