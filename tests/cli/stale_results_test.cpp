// End to end: results cannot be stale. A command run into the folder of an earlier one removes
// that one's results once its own inputs passed their checks and before it works, so that a
// failure (exit 1) leaves nothing that looks like its own finished result: no old
// execution/metrics.json of `cosim mapf --execute`. A refusal (exit 2, bad input) touches nothing:
// the earlier results stay, complete and as they were.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

const char* kQuickFlight =
    "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [4, 2, 1]}]\n"
    "sim: {max_time: 10}\n";

TEST(StaleResults, ARefusedRerunIntoAnOldRunFolderLeavesTheOldResultsAsTheyWere) {
  const fs::path dir = freshDir("stale-refused");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << kQuickFlight;
  const fs::path out = dir / "run";
  const CommandResult first =
      runCosim("run " + (dir / "s.yaml").string() + " --no-video --quiet --out " + out.string());
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_TRUE(jsonTrue(slurp(out / "metrics.json"), "reached_goal"));
  ASSERT_TRUE(fs::exists(out / "index.html"));

  std::map<std::string, std::string> before;
  for (const char* old : {"metrics.json", "index.html", "timeseries.csv", "path.csv", "final.png"})
    before[old] = slurp(out / old);
  const CommandResult refused =
      runCosim("run " + (dir / "s.yaml").string() +
               " --no-video --quiet --set sim.timestep=abc --out " + out.string());
  EXPECT_EQ(refused.status, 2) << refused.err;
  for (const auto& [name, text] : before)
    EXPECT_EQ(slurp(out / name), text) << name << " of the earlier run changed";
  fs::remove_all(dir);
}

TEST(StaleResults, AFailingMapfExecuteIntoAnOldFolderLeavesNoOldExecutionMetrics) {
  const fs::path dir = freshDir("stale-mapf");
  const std::string map = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map";
  const std::string scen = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8-random-1.scen";
  const CommandResult first = runCosim("mapf " + map + " " + scen +
                                       " --agents 2 --planner cbs --execute --out " + dir.string());
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_TRUE(jsonTrue(slurp(dir / "execution" / "metrics.json"), "reached_goal"));

  // Planning fails (a time limit no search meets): exit 1, and the old execution is gone.
  const std::string den = COSIM_SOURCE_DIR "/experiments/maps/";
  const CommandResult failed =
      runCosim("mapf " + den + "random-32-32-10.map " + den +
               "random-32-32-10-random-1.scen --agents 150 --planner cbs --time-limit 0.001 "
               "--execute --out " +
               dir.string());
  EXPECT_EQ(failed.status, 1) << failed.err;
  EXPECT_FALSE(fs::exists(dir / "execution" / "metrics.json"));
  EXPECT_FALSE(fs::exists(dir / "execution" / "timeseries.csv"));
  EXPECT_FALSE(jsonTrue(slurp(dir / "mapf.json"), "success"));

  // Refused (bad input): the earlier plan and execution stay as they were.
  ASSERT_EQ(runCosim("mapf " + map + " " + scen + " --agents 2 --planner cbs --execute --out " +
                     dir.string())
                .status,
            0);
  const std::string plan = slurp(dir / "mapf.json");
  const std::string metrics = slurp(dir / "execution" / "metrics.json");
  const CommandResult refused =
      runCosim("mapf " + map + " " + scen + " --agents 2 --planner teleport --execute --out " +
               dir.string());
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_EQ(slurp(dir / "mapf.json"), plan);
  EXPECT_EQ(slurp(dir / "execution" / "metrics.json"), metrics);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
