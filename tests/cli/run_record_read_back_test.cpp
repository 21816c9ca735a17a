// `cosim render`, export-mcap and compare-real read a run's record back from its folder with one
// reader (cli/run_folder.h): what it reads back is the record the run wrote, as far as the
// folder's files hold it: the setup, the log (to 9 significant digits), the world and the tracking
// errors; not the flight metrics, which need the arrivals only metrics.json holds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/run_folder.h"
#include "run/run_pipeline.h"
#include "sim/scenario.h"
#include "tests/run/robot_and_uav_scenario.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

const std::string& kRobotAndUav = test::kRobotAndUavScenario;

TEST(RunRecordReadBack, TheRecordReadFromARunFolderIsTheRecordTheRunWrote) {
  const auto dir = test::makeFreshDir("record-read-back");
  const auto file = dir / "mixed.yaml";
  std::ofstream(file) << kRobotAndUav;
  RunRequest request;
  request.out_dir = dir / "run";
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  const RunRecord written = executeRun(loadScenario(file.string()), request);
  ASSERT_EQ(written.outcome, RunOutcome::Succeeded) << written.message;

  const Scenario scenario = cli::readRunScenario(request.out_dir);
  const RunRecord read = cli::readRunRecord(request.out_dir, scenario);
  ASSERT_EQ(read.setup.vehicles.size(), written.setup.vehicles.size());
  for (std::size_t v = 0; v < read.setup.vehicles.size(); ++v) {
    EXPECT_EQ(read.setup.vehicles[v].kind, written.setup.vehicles[v].kind) << v;
    EXPECT_EQ(read.errorReferenceOf(v), written.errorReferenceOf(v)) << v;
    EXPECT_EQ(read.log.vehicles[v].name, written.log.vehicles[v].name) << v;
    EXPECT_EQ(read.log.vehicles[v].radius, written.log.vehicles[v].radius) << v;
    const auto& ea = read.metrics.tracking_errors[v];
    const auto& eb = written.metrics.tracking_errors[v];
    ASSERT_EQ(ea.size(), eb.size()) << v;
    ASSERT_GT(ea.size(), 100u);
    double largest = 0.0;
    for (std::size_t k = 0; k < ea.size(); ++k) {
      EXPECT_NEAR(ea[k], eb[k], 1e-6) << v << " " << k;
      largest = std::max(largest, ea[k]);
    }
    EXPECT_GT(largest, 1e-4) << v;  // errors that would show a wrong reference
  }
  EXPECT_EQ(read.setup.robots, written.setup.robots);
  EXPECT_EQ(read.setup.quadrotors, written.setup.quadrotors);
  ASSERT_TRUE(read.world);
  EXPECT_EQ(read.world->vehicles().size(), 2u);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim
