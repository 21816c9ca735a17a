// End to end: a shell starts a background job with SIGINT ignored, so that Ctrl-C at the terminal
// reaches only the foreground job. cosim keeps an inherited SIG_IGN (it replaced it with its own
// handler, and a Ctrl-C meant for another program stopped the run); SIGTERM still stops it.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/support/spawned_cosim.h"
#include "tests/support/test_files.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

TEST(InheritedSigint, ARunStartedWithSigintIgnoredKeepsItIgnoredAndStopsOnSigterm) {
  const fs::path dir = freshDir("sigint-ignored");
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  // As `cosim run ... &` in a script starts it: the child inherits SIG_IGN across exec.
  struct sigaction ignore {
  }, previous{};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ASSERT_EQ(sigaction(SIGINT, &ignore, &previous), 0);
  const pid_t pid = spawnCosim({"run", "--no-video", "--out", out.string(), "--set",
                                "sim.max_time=600", "--set", "trajectory.max_speed=0.05"},
                               err);
  sigaction(SIGINT, &previous, nullptr);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);
  kill(pid, SIGINT);
  // Still flying a second later: the signal was ignored, not merely slow to act on.
  std::this_thread::sleep_for(std::chrono::seconds(1));
  int raw = 0;
  EXPECT_EQ(waitpid(pid, &raw, WNOHANG), 0) << slurp(err);
  EXPECT_EQ(slurp(err).find("interrupted"), std::string::npos) << slurp(err);
  kill(pid, SIGTERM);
  EXPECT_EQ(waitExitWithin(pid, std::chrono::seconds(120)), 1);
  EXPECT_NE(slurp(err).find("interrupted"), std::string::npos) << slurp(err);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
