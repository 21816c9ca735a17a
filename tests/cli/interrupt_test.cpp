// End to end: SIGTERM (or SIGINT) during `cosim run` stops the run cleanly: exit 1, one line
// saying so, and no file in the run folder that looks finished (metrics.json is the mark of a
// complete run, and no temporary file is left behind). Running again into the same folder then
// completes normally.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"
#include "tests/support/spawned_cosim.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

void expectNoFinishedOrTemporaryFiles(const fs::path& dir) {
  EXPECT_FALSE(fs::exists(dir / "metrics.json"));
  if (!fs::exists(dir)) return;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// Waits for the exit; the status as waitExitWithin gives it, and the seconds it took.
std::pair<int, double> timedExit(pid_t pid, std::chrono::seconds limit) {
  const auto sent = std::chrono::steady_clock::now();
  const int status = waitExitWithin(pid, limit);
  return {status, std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
}

void interruptDuringFlight(int signal_number, const std::string& name) {
  const fs::path dir = freshDir("interrupt-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  // A long, slow flight (0.05 m/s for 600 s of simulated time, seconds of wall time): the signal
  // surely arrives while the vehicle is in the air.
  const pid_t pid = spawnCosim({"run", "--no-video", "--out", out.string(), "--set",
                                "sim.max_time=600", "--set", "trajectory.max_speed=0.05"},
                               err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: flying", std::chrono::seconds(120))) << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, signal_number);
  // Within 3 s: the loop looks at the stop request at every control step.
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(120));
  EXPECT_EQ(status, 1);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted"), std::string::npos) << slurp(err);
  expectNoFinishedOrTemporaryFiles(out);
  fs::remove_all(dir);
}

// 500 quadrotors planned as one team (experiments/scenarios/swarm500.yaml): a SIGINT or SIGTERM
// while the team's trajectories are being smoothed and repaired (a stage that used to run for
// minutes without looking at stop requests) ends the run within 3 s (its "interrupted" line),
// exit 1, no finished files.
void interruptTeamSmoothing(int signal_number, const std::string& name) {
  const fs::path dir = freshDir("interrupt-team500-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t pid = spawnCosim({"run", COSIM_SOURCE_DIR "/experiments/scenarios/swarm500.yaml",
                                "--no-video", "--out", out.string()},
                               err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "steps found in", std::chrono::seconds(120))) << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(slurp(err).find("cosim: flying"), std::string::npos) << "planned too soon to test";
  kill(pid, signal_number);
  // The run has ended when it says so; the process's own teardown after that (seconds under
  // AddressSanitizer's leak check on a loaded machine) is not the planner's to shorten.
  EXPECT_TRUE(waitForText(err, "interrupted", std::chrono::seconds(3))) << slurp(err);
  EXPECT_EQ(waitExitWithin(pid, std::chrono::seconds(60)), 1);
  expectNoFinishedOrTemporaryFiles(out);
  fs::remove_all(dir);
}

TEST(Interrupt, SigtermDuringTheTeamPlanningOf500QuadrotorsEndsTheRunWithinThreeSeconds) {
  interruptTeamSmoothing(SIGTERM, "term");
}

TEST(Interrupt, SigintDuringTheTeamPlanningOf500QuadrotorsEndsTheRunWithinThreeSeconds) {
  interruptTeamSmoothing(SIGINT, "int");
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
  ASSERT_EQ(waitExitWithin(pid, std::chrono::seconds(120)), 1);
  expectNoFinishedOrTemporaryFiles(out);

  const CommandResult again = runCosim("run --no-video --quiet --out " + out.string());
  EXPECT_EQ(again.status, 0) << again.err;
  const std::string metrics = slurp(out / "metrics.json");
  EXPECT_TRUE(jsonTrue(metrics, "reached_goal")) << metrics;
  EXPECT_NE(metrics.find("\"end_reason\": \"goal\""), std::string::npos) << metrics;
  fs::remove_all(dir);
}

// --- Interrupted while rendering the video -------------------------------------------------

// The first file in `dir` whose name contains `part` (ffmpeg's output in progress), or "".
fs::path partialFile(const fs::path& dir, const std::string& part) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().find(part) != std::string::npos) return e.path();
  return {};
}

// The bytes ffmpeg has written under `p`: a file, or the files in cosim's work folder for it
// (.video.mp4.part<pid>/video.mp4, core/temporary_name.h).
std::uintmax_t writtenBytes(const fs::path& p) {
  std::error_code ec;
  if (!fs::is_directory(p, ec)) return fs::file_size(p, ec) > 0 && !ec ? fs::file_size(p, ec) : 0;
  std::uintmax_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(p, ec))
    if (e.is_regular_file(ec)) n += e.file_size(ec);
  return n;
}

// Waits (up to `limit`) until ffmpeg has written into a temporary file in `dir`.
bool waitForPartialVideo(const fs::path& dir, std::chrono::seconds limit) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    const fs::path p = partialFile(dir, ".part");
    if (!p.empty() && writtenBytes(p) > 0) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

// Processes (other than the test) whose command line mentions `text`: an ffmpeg left running
// would be one.
std::vector<pid_t> processesMentioning(const std::string& text) {
  std::vector<pid_t> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos || pid == std::to_string(getpid()))
      continue;
    std::string cmdline = slurp(e.path() / "cmdline");
    std::replace(cmdline.begin(), cmdline.end(), '\0', ' ');
    if (cmdline.find(text) != std::string::npos) found.push_back(std::stoi(pid));
  }
  return found;
}

// Starts `cosim run` (in its own process group) making a small video of a slowed-down replay:
// thousands of 160x96 frames, so rendering is surely under way for a while when a signal comes.
pid_t spawnSlowVideoRun(const fs::path& out, const fs::path& err) {
  return spawnCosim({"run", "--no-images", "--out", out.string(), "--set", "render.width=160",
                     "--set", "render.height=96", "--set", "render.speedup=0.2"},
                    err, /*own_group=*/true);
}

void interruptDuringVideo(int signal_number, bool to_group, const std::string& name) {
  const fs::path dir = freshDir("interrupt-video-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t pid = spawnSlowVideoRun(out, err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: rendering video.mp4", std::chrono::seconds(120)))
      << slurp(err);
  ASSERT_TRUE(waitForPartialVideo(out, std::chrono::seconds(60))) << slurp(err);
  kill(to_group ? -pid : pid, signal_number);
  // Within 3 s: the frame loop polls the flag (the whole video would take many seconds more).
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(15));
  EXPECT_EQ(status, 1) << slurp(err);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + out.string() + " holds no finished run"),
            std::string::npos)
      << slurp(err);
  expectNoFinishedOrTemporaryFiles(out);
  EXPECT_FALSE(fs::exists(out / "video.mp4"));
  EXPECT_FALSE(fs::exists(out / "index.html"));
  EXPECT_EQ(partialFile(out, ".part"), fs::path()) << "ffmpeg's partial output was left behind";
  EXPECT_TRUE(processesMentioning(out.string()).empty()) << "ffmpeg still running";
  fs::remove_all(dir);
}

TEST(Interrupt, CtrlCDuringTheVideoStopsRenderingDeletesThePartialVideoAndExitsOne) {
  // SIGINT to the whole process group, as the terminal sends it: ffmpeg must not die under
  // cosim (which then died of SIGPIPE writing into the pipe, leaving the partial file).
  interruptDuringVideo(SIGINT, /*to_group=*/true, "ctrl-c");
}

TEST(Interrupt, SigtermDuringTheVideoStopsRenderingDeletesThePartialVideoAndExitsOne) {
  interruptDuringVideo(SIGTERM, /*to_group=*/false, "term");
}

TEST(Interrupt, CtrlCDuringCosimRenderExitsOneAndWritesNoVideo) {
  const fs::path dir = freshDir("interrupt-render");
  fs::create_directories(dir);
  const fs::path run = dir / "run", err = dir / "err", video = run / "replay.mp4";
  const CommandResult flown = runCosim("run --no-video --no-images --quiet --out " + run.string());
  ASSERT_EQ(flown.status, 0) << flown.err;
  const pid_t pid = spawnCosim({"render", run.string(), "--width", "160", "--height", "96",
                                "--speedup", "0.2", "--out", video.string()},
                               err, /*own_group=*/true);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForPartialVideo(run, std::chrono::seconds(60))) << slurp(err);
  kill(-pid, SIGINT);
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(15));
  EXPECT_EQ(status, 1) << slurp(err);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + video.string() + " was not written"),
            std::string::npos)
      << slurp(err);
  EXPECT_FALSE(fs::exists(video));
  EXPECT_EQ(partialFile(run, ".part"), fs::path());
  EXPECT_TRUE(processesMentioning(video.filename().string() + ".part").empty())
      << "ffmpeg still running";
  // The run itself is untouched and still finished.
  EXPECT_TRUE(fs::exists(run / "metrics.json"));
  fs::remove_all(dir);
}

TEST(VideoFailure, FfmpegDyingMidVideoIsAnErrorMessageNotADeathBySigpipe) {
  const fs::path dir = freshDir("ffmpeg-dies");
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  const pid_t pid = spawnSlowVideoRun(out, err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForPartialVideo(out, std::chrono::seconds(120))) << slurp(err);
  const std::vector<pid_t> ffmpeg = processesMentioning(".video.mp4.part" + std::to_string(pid));
  ASSERT_EQ(ffmpeg.size(), 1u);
  kill(ffmpeg.front(), SIGKILL);
  // cosim's next write into the pipe fails (EPIPE): it reports that, as an internal error.
  EXPECT_EQ(waitExitWithin(pid, std::chrono::seconds(15)), 3) << slurp(err);
  EXPECT_NE(slurp(err).find("cosim: internal error: ffmpeg failed while writing"),
            std::string::npos)
      << slurp(err);
  EXPECT_EQ(partialFile(out, ".part"), fs::path());
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
  fs::remove_all(dir);
}

// --- Interrupted while planning, into the folder of an earlier finished run -----------------

// A scenario whose goal stands in a closed box: RRT grows its tree towards it until its time
// limit (minutes) or node limit (ten million), so a signal surely arrives while it plans.
const char* kUnreachableGoal =
    "world:\n  bounds: {min: [0, 0, 0], max: [40, 40, 10]}\n  obstacles:\n"
    "    - {type: box, pos: [30, 30, 0.5], size: [6, 6, 0.4]}\n"
    "    - {type: box, pos: [30, 30, 9.5], size: [6, 6, 0.4]}\n"
    "    - {type: box, pos: [27, 30, 5], size: [0.4, 6, 9.4]}\n"
    "    - {type: box, pos: [33, 30, 5], size: [0.4, 6, 9.4]}\n"
    "    - {type: box, pos: [30, 27, 5], size: [6, 0.4, 9.4]}\n"
    "    - {type: box, pos: [30, 33, 5], size: [6, 0.4, 9.4]}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 2], goal: [30, 30, 5]}]\n"
    "planner: {name: rrt, max_nodes: 10000000, time_limit: 600}\n";

TEST(Interrupt, SigtermWhilePlanningARerunLeavesNeitherTheOldNorANewResult) {
  const fs::path dir = freshDir("interrupt-planning");
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  // An earlier run finished in the folder: its metrics.json said reached_goal true.
  std::ofstream(dir / "quick.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [4, 2, 1]}]\n"
         "sim: {max_time: 10}\n";
  const CommandResult first = runCosim("run " + (dir / "quick.yaml").string() +
                                       " --no-video --quiet --out " + out.string());
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_TRUE(jsonTrue(slurp(out / "metrics.json"), "reached_goal"));

  std::ofstream(dir / "walled.yaml") << kUnreachableGoal;
  const pid_t pid =
      spawnCosim({"run", (dir / "walled.yaml").string(), "--no-video", "--out", out.string()}, err);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "planning uav1 with rrt", std::chrono::seconds(120))) << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(pid, SIGTERM);
  // The planner polls the stop request with its deadline: it ends at once (within 3 s), not at
  // 600 s.
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(30));
  EXPECT_EQ(status, 1);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + out.string() + " holds no finished run"),
            std::string::npos)
      << slurp(err);
  expectNoFinishedOrTemporaryFiles(out);
  for (const char* old : {"index.html", "timeseries.csv", "path.csv"})
    EXPECT_FALSE(fs::exists(out / old)) << old << " of the earlier run is still there";
  fs::remove_all(dir);
}

void interruptCbs(int signal_number, const std::string& name, bool blocked_at_start = false) {
  const fs::path dir = freshDir("interrupt-cbs-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "mapf", err = dir / "err";
  const std::string data = COSIM_SOURCE_DIR "/experiments/maps/";
  // An earlier, solved instance left its mapf.json in the folder.
  const CommandResult first =
      runCosim("mapf " + data + "empty-8-8.map " + data +
               "empty-8-8-random-1.scen --agents 2 --planner cbs --out " + out.string());
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_TRUE(fs::exists(out / "mapf.json"));
  // A launcher may start cosim with the signals blocked (the mask is inherited across exec):
  // they then stayed pending, and CBS went on to its time limit and wrote its result.
  sigset_t signals, previous;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  if (blocked_at_start) pthread_sigmask(SIG_BLOCK, &signals, &previous);
  // 200 agents on a 32 x 32 map with obstacles: CBS searches for minutes (time limit 600 s).
  const pid_t pid = spawnCosim(
      {"mapf", data + "random-32-32-10.map", data + "random-32-32-10-random-1.scen", "--agents",
       "200", "--planner", "cbs", "--time-limit", "600", "--out", out.string()},
      err);
  if (blocked_at_start) pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, signal_number);
  // Within 3 s of the signal: CBS polls the stop request in its high-level loop and every 256
  // expansions of its low-level A* (it ended in about 0.02 s when measured).
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(30));
  EXPECT_EQ(status, 1);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + out.string() + " holds no plan"), std::string::npos)
      << slurp(err);
  EXPECT_FALSE(fs::exists(out / "mapf.json"));
  EXPECT_FALSE(fs::exists(out / "paths.csv"));
  fs::remove_all(dir);
}

TEST(Interrupt, SigtermDuringALongCbsSearchEndsItWithoutAPlan) {
  interruptCbs(SIGTERM, "term");
}

TEST(Interrupt, SigintDuringALongCbsSearchEndsItWithoutAPlan) {
  interruptCbs(SIGINT, "int");
}

TEST(Interrupt, SignalsBlockedWhenCosimStartsStillEndACbsSearch) {
  interruptCbs(SIGTERM, "blocked", /*blocked_at_start=*/true);
}

// `cosim plan` with RRT* given an hour (time_limit 3600) towards a walled-in goal: SIGINT ends it
// within 3 s, exit 1, and no plan.json or path.csv.
TEST(Interrupt, SigintWhileCosimPlanSearchesWritesNoPlan) {
  const fs::path dir = freshDir("interrupt-plan");
  fs::create_directories(dir);
  const fs::path out = dir / "plan", err = dir / "err";
  std::ofstream(dir / "walled.yaml") << kUnreachableGoal;
  const pid_t pid = spawnCosim({"plan", (dir / "walled.yaml").string(), "--planner", "rrt_star",
                                "--set", "planner.time_limit=3600", "--out", out.string()},
                               err);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(pid, SIGINT);
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(30));
  EXPECT_EQ(status, 1);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + out.string() + " holds no plan"), std::string::npos)
      << slurp(err);
  EXPECT_FALSE(fs::exists(out / "plan.json"));
  EXPECT_FALSE(fs::exists(out / "path.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
