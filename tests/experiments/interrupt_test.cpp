// End to end: SIGTERM (or SIGINT) during `cosim run` stops the run cleanly: exit 1, one line
// saying so, and no file in the run folder that looks finished (metrics.json is the mark of a
// complete run, and no temporary file is left behind). Running again into the same folder then
// completes normally.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "tests/experiments/cli_test_support.h"

extern char** environ;

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// Starts `cosim args...` with stderr sent to `err_file`; returns its pid.
pid_t spawnCosim(const std::vector<std::string>& args, const fs::path& err_file) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  std::vector<std::string> all = {COSIM_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, COSIM_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Waits (up to `limit`) until the file contains `text`.
bool waitForText(const fs::path& file, const std::string& text, std::chrono::seconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (slurp(file).find(text) != std::string::npos) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

int waitExit(pid_t pid) {
  int raw = 0;
  waitpid(pid, &raw, 0);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

void expectNoFinishedOrTemporaryFiles(const fs::path& dir) {
  EXPECT_FALSE(fs::exists(dir / "metrics.json"));
  if (!fs::exists(dir)) return;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

void interruptDuringFlight(int signal_number, const std::string& name) {
  const fs::path dir = freshDir("interrupt-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  // A long, slow flight (0.05 m/s for 600 s of simulated time, seconds of wall time): the signal
  // surely arrives while the vehicle is in the air.
  const pid_t pid =
      spawnCosim({"run", "--no-video", "--out", out.string(), "--set", "sim.max_time=600", "--set",
                  "trajectory.max_speed=0.05"},
                 err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, signal_number);
  EXPECT_EQ(waitExit(pid), 1);
  EXPECT_NE(slurp(err).find("interrupted"), std::string::npos) << slurp(err);
  expectNoFinishedOrTemporaryFiles(out);
  fs::remove_all(dir);
}

TEST(Interrupt, SigtermDuringFlightExitsOneAndLeavesNoFinishedRun) {
  interruptDuringFlight(SIGTERM, "term");
}

TEST(Interrupt, SigintDuringFlightExitsOneAndLeavesNoFinishedRun) {
  interruptDuringFlight(SIGINT, "int");
}

TEST(Interrupt, RunningAgainIntoTheInterruptedFolderCompletes) {
  const fs::path dir = freshDir("interrupt-resume");
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t pid = spawnCosim({"run", "--no-video", "--out", out.string()}, err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);
  kill(pid, SIGTERM);
  ASSERT_EQ(waitExit(pid), 1);
  expectNoFinishedOrTemporaryFiles(out);

  const CommandResult again = runCosim("run --no-video --quiet --out " + out.string());
  EXPECT_EQ(again.status, 0) << again.err;
  const std::string metrics = slurp(out / "metrics.json");
  EXPECT_TRUE(jsonTrue(metrics, "reached_goal")) << metrics;
  EXPECT_NE(metrics.find("\"end_reason\": \"goal\""), std::string::npos) << metrics;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
