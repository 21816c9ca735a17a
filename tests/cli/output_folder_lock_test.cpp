// End to end: two commands writing into one output folder at once would mix their files (one
// run's path and time series with the other's metrics.json). The second is refused with exit 2
// naming the folder and the first one's process id; the first finishes undisturbed, and once it
// has ended the folder is free again.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "tests/support/cosim_command.h"
#include "tests/support/spawned_cosim.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

const char* kScenario =
    "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
    "        obstacles: [{type: box, pos: [10, 10, 3], size: [2, 8, 6]}]}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n"
    "planner: {name: astar, resolution: 0.5}\n"
    // A slow flight: still in the air while the second command starts.
    "trajectory: {mode: minimum_snap, max_speed: 0.05, max_acceleration: 3.0}\n";

TEST(OutputFolderLock, ASecondRunIntoTheFolderOfARunningOneExitsTwoNamingItsPid) {
  const fs::path dir = freshDir("lock-run");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << kScenario;
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t first = spawnCosim({"run", (dir / "s.yaml").string(), "--no-video", "--out",
                                  out.string(), "--set", "sim.max_time=600"},
                                 err);
  ASSERT_GT(first, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);

  const CommandResult second =
      runCosim("run " + (dir / "s.yaml").string() + " --no-video --quiet --out " + out.string());
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(second.err.find(out.string() + ": --out: the folder is in use by another cosim (pid " +
                            std::to_string(first) + ")"),
            std::string::npos)
      << second.err;
  EXPECT_EQ(std::count(second.err.begin(), second.err.end(), '\n'), 1) << second.err;
  // The first run's files are untouched by the refused one, and it ends as it would have.
  kill(first, SIGTERM);
  EXPECT_EQ(waitExitWithin(first, std::chrono::seconds(120)), 1);
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
  EXPECT_FALSE(fs::exists(out / ".cosim.lock"));  // the holder removed it as it let go

  const CommandResult third = runCosim(
      "run " + (dir / "s.yaml").string() +
      " --no-video --no-images --quiet --set trajectory.max_speed=3 --out " + out.string());
  EXPECT_EQ(third.status, 0) << third.err;
  EXPECT_TRUE(fs::exists(out / "metrics.json"));
  fs::remove_all(dir);
}

TEST(OutputFolderLock, ALockLeftByAKilledRunDoesNotBlockTheNextOne) {
  const fs::path dir = freshDir("lock-killed");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << kScenario;
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t first = spawnCosim({"run", (dir / "s.yaml").string(), "--no-video", "--out",
                                  out.string(), "--set", "sim.max_time=600"},
                                 err);
  ASSERT_GT(first, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);
  kill(first, SIGKILL);
  EXPECT_EQ(waitExitWithin(first, std::chrono::seconds(30)), -1);
  EXPECT_TRUE(fs::exists(out / ".cosim.lock"));  // left behind, but no longer locked
  const CommandResult next = runCosim(
      "run " + (dir / "s.yaml").string() +
      " --no-video --no-images --quiet --set trajectory.max_speed=3 --out " + out.string());
  EXPECT_EQ(next.status, 0) << next.err;
  fs::remove_all(dir);
}

// Two sweeps into one folder: the second would delete the first one's running job folders.
// The shards of one sweep share it (each shard once).
TEST(OutputFolderLock, ASecondSweepIntoTheFolderOfARunningOneExitsTwo) {
  const fs::path dir = freshDir("lock-sweep");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml") << kScenario << "sim: {max_time: 600}\n";
  std::ofstream(dir / "sweep.yaml") << "scenarios: [s.yaml]\nvary: {sim.seed: [1, 2]}\n"
                                       "output: {video: false}\n";
  const fs::path out = dir / "out", err = dir / "err";
  const pid_t first = spawnCosim(
      {"sweep", (dir / "sweep.yaml").string(), "--jobs", "1", "--out", out.string()}, err);
  ASSERT_GT(first, 0);
  // The first job's `cosim run` holds its own job folder.
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(out / "jobs/0000/.cosim.lock") &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(120))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(fs::exists(out / "jobs/0000/.cosim.lock")) << slurp(err);
  const std::string sweep = "sweep " + (dir / "sweep.yaml").string() + " --out " + out.string();
  const CommandResult second = runCosim(sweep + " --quiet");
  EXPECT_EQ(second.status, 2) << second.err;
  EXPECT_NE(
      second.err.find("the folder is in use by another cosim (pid " + std::to_string(first) + ")"),
      std::string::npos)
      << second.err;
  const CommandResult shard = runCosim(sweep + " --quiet --shard 2/2");
  EXPECT_EQ(shard.status, 2) << shard.err;             // a whole sweep excludes shards too
  EXPECT_TRUE(fs::exists(out / "jobs/0000/log.txt"));  // the running job's folder is still there
  kill(first, SIGINT);
  EXPECT_EQ(waitExitWithin(first, std::chrono::seconds(120)), 1) << slurp(err);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
