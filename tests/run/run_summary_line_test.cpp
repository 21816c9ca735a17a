// The console line of a finished run: metrics.json's top-level (pooled) figures, whose they are,
// and what the error was measured against; the last line names the pages to open.
#include "run/run_summary_line.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_files.h"

using namespace cosim;

namespace {

// A two-vehicle team whose first member's figures differ from the team's pooled ones.
nlohmann::ordered_json twoVehicleTeam() {
  return nlohmann::ordered_json::parse(R"({
    "reached_goal": true, "collisions": 0, "flight_time_s": 20.5, "rmse_m": 0.0173,
    "max_error_m": 0.137, "min_clearance_m": 0.141, "sim_speed_x": 3.5,
    "error_reference": "trajectory",
    "vehicles": [
      {"name": "a", "rmse_m": 0.0203, "max_error_m": 0.1246, "min_clearance_m": 0.396},
      {"name": "b", "rmse_m": 0.0131, "max_error_m": 0.137, "min_clearance_m": 0.141}]})");
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
  nlohmann::ordered_json m = twoVehicleTeam();
  m["error_reference"] = "timed_plan";
  m["robots"] = 2;
  const std::string line = runSummaryLine(m);
  EXPECT_NE(line.find("(against the timed plan)"), std::string::npos) << line;
  EXPECT_EQ(line.find("trajectory"), std::string::npos) << line;
}

TEST(RunSummaryLine, RobotsWithQuadrotorsPrintBothGroups) {
  nlohmann::ordered_json m = twoVehicleTeam();
  m["error_reference"] = "timed_plan";
  m["robots"] = 1;
  m["uavs"] = 1;
  m["uav_rmse_m"] = 0.031;
  m["uav_max_error_m"] = 0.09;
  const std::string line = runSummaryLine(m);
  EXPECT_EQ(line.rfind("robots (1, pooled): ", 0), 0u) << line;
  EXPECT_NE(line.find("quadrotors (1, pooled): rmse 0.031 m, max error 0.09 m"), std::string::npos)
      << line;
}

TEST(RunSummaryLine, ASingleVehicleLineHasNoTeamPrefix) {
  nlohmann::ordered_json m = twoVehicleTeam();
  m["vehicles"].erase(1);
  m["error_reference"] = "path";
  const std::string line = runSummaryLine(m);
  EXPECT_EQ(line.rfind("reached_goal yes", 0), 0u) << line;
  EXPECT_NE(line.find("(against the planned path)"), std::string::npos) << line;
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
