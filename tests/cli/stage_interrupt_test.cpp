// End to end: SIGINT and SIGTERM end `cosim run` within 3 s in the stages that used to ignore
// them: compiling a world fragment's meshes (MuJoCo's compiler cannot be interrupted: the mesh
// budget keeps it short, and the run looks at the stop request as soon as it returns), and
// plotting the figures (gnuplot is killed on a stop; it ran for 15 s on 500 quadrotors' flights
// while a SIGTERM waited). Exit 1, one "interrupted" line, no finished file, no gnuplot left.
// The other stages' signal tests are in interrupt_test.cpp.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cosim_command.h"
#include "tests/support/spawned_cosim.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// Waits for the exit; the status as waitExitWithin gives it, and the seconds it took.
std::pair<int, double> timedExit(pid_t pid, std::chrono::seconds limit) {
  const auto sent = std::chrono::steady_clock::now();
  const int status = waitExitWithin(pid, limit);
  return {status, std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
}

// Processes whose working folder lies under `dir` (a gnuplot left running in its scratch folder
// would be one).
std::vector<pid_t> processesWorkingIn(const fs::path& dir) {
  std::vector<pid_t> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string pid = e.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    const fs::path cwd = fs::read_symlink(e.path() / "cwd", ec);
    if (!ec && cwd.string().rfind(dir.string(), 0) == 0) found.push_back(std::stoi(pid));
  }
  return found;
}

void expectNoFinishedRun(const fs::path& out) {
  EXPECT_FALSE(fs::exists(out / "metrics.json"));
  EXPECT_FALSE(fs::exists(out / "index.html"));
  if (!fs::exists(out)) return;
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".part"), std::string::npos) << e.path();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
  }
}

// An inline mesh of `n` points on a unit sphere (a Fibonacci lattice): every point is a vertex of
// its convex hull, MuJoCo's slowest case.
std::string sphereMesh(const std::string& name, int n) {
  std::ostringstream v;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z), a = 2.399963 * i;
    v << r * std::cos(a) << ' ' << r * std::sin(a) << ' ' << z << ' ';
  }
  return "<mesh name=\"" + name + "\" vertex=\"" + v.str() + "\"/>";
}

// A scenario whose world fragment holds a mesh at a mesh's budget (10000 vertices, all on its
// hull: about 0.2 s of CPU time to compile), followed by a slow flight: without a stop after
// loading, the run would plan and fly for minutes.
fs::path meshWorld(const fs::path& dir) {
  std::ofstream(dir / "rocks.xml")
      << "<mujoco>\n<asset>" << sphereMesh("a", 10000) << "</asset>\n<worldbody>"
      << "<geom type=\"mesh\" mesh=\"a\" pos=\"10 10 1\"/>"
      << "</worldbody>\n</mujoco>\n";
  std::ofstream(dir / "s.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: rocks.xml}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 2, 1]}]\n"
         "trajectory: {mode: minimum_snap, max_speed: 0.05}\nsim: {max_time: 600}\n";
  return dir / "s.yaml";
}

// CPU seconds the process has used (user + system, /proc/PID/stat fields 14 and 15).
double cpuSeconds(pid_t pid) {
  std::istringstream stat(slurp("/proc/" + std::to_string(pid) + "/stat"));
  std::string field;
  double ticks = 0.0;
  for (int i = 1; i <= 15 && stat >> field; ++i)
    if (i >= 14) ticks += std::stod(field);
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// Whether the process has a handler for `signal_number` (the SigCgt mask of /proc/PID/status):
// before cosim installs its handlers a signal would end it by the default action.
bool catchesSignal(pid_t pid, int signal_number) {
  std::istringstream status(slurp("/proc/" + std::to_string(pid) + "/status"));
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (signal_number - 1)) & 1U;
  return false;
}

void interruptWhileLoading(int signal_number, const std::string& name) {
  const fs::path dir = freshDir("interrupt-loading-" + name);
  fs::create_directories(dir);
  const fs::path out = dir / "run", err = dir / "err";
  const fs::path scenario = meshWorld(dir);
  const pid_t pid =
      spawnCosim({"run", scenario.string(), "--no-video", "--out", out.string()}, err);
  ASSERT_GT(pid, 0);
  // Past its start (the handlers are installed first thing; a sanitizer build spends a tenth of
  // a second of CPU before that) and into MuJoCo's compilation: the scenario and the fragment are
  // read and checked in a few tens of milliseconds after the handlers.
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!catchesSignal(pid, signal_number) && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const double started = cpuSeconds(pid);
  while (cpuSeconds(pid) < started + 0.1 && std::chrono::steady_clock::now() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const std::string before = slurp(err);
  kill(pid, signal_number);
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(60));
  EXPECT_EQ(status, 1) << slurp(err);
  EXPECT_LT(seconds, 3.0);
  const std::string said = slurp(err);
  EXPECT_EQ(before.find("planning"), std::string::npos) << "loaded too soon to test: " << before;
  // Stopped as soon as the world was compiled, before planning.
  EXPECT_EQ(said.find("planning"), std::string::npos) << said;
  EXPECT_NE(said.find("interrupted; " + out.string() + " holds no finished run"), std::string::npos)
      << said;
  expectNoFinishedRun(out);
  fs::remove_all(dir);
}

TEST(StageInterrupt, SigintWhileMujocoCompilesAFragmentsMeshesExitsOneWithinThreeSeconds) {
  interruptWhileLoading(SIGINT, "int");
}

TEST(StageInterrupt, SigtermWhileMujocoCompilesAFragmentsMeshesExitsOneWithinThreeSeconds) {
  interruptWhileLoading(SIGTERM, "term");
}

// A quick run (a 2 m hop in a small world, small final.png) whose figures are drawn by a
// stand-in for gnuplot that takes 60 s (first on PATH): without the stop, plotting would last a
// minute, so only killing it ends the run within 3 s.
void interruptWhilePlotting(int signal_number, const std::string& name) {
  const fs::path dir = freshDir("interrupt-plotting-" + name);
  fs::create_directories(dir / "bin");
  const fs::path out = dir / "run", err = dir / "err";
  {
    std::ofstream slow(dir / "bin" / "gnuplot");
    slow << "#!/bin/sh\nexec sleep 60\n";
  }
  fs::permissions(dir / "bin" / "gnuplot", fs::perms::owner_all);
  std::ofstream(dir / "quick.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [4, 2, 1]}]\n"
         "sim: {max_time: 10}\nrender: {width: 160, height: 96}\n";
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin";
  setenv("PATH", ((dir / "bin").string() + ":" + path).c_str(), 1);
  const pid_t pid =
      spawnCosim({"run", (dir / "quick.yaml").string(), "--no-video", "--out", out.string()}, err);
  setenv("PATH", path.c_str(), 1);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(err, "cosim: plotting figures/", std::chrono::seconds(120)))
      << slurp(err);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_FALSE(processesWorkingIn(out).empty()) << "gnuplot is not running";
  kill(pid, signal_number);
  const auto [status, seconds] = timedExit(pid, std::chrono::seconds(90));
  EXPECT_EQ(status, 1) << slurp(err);
  EXPECT_LT(seconds, 3.0);
  EXPECT_NE(slurp(err).find("interrupted; " + out.string() + " holds no finished run"),
            std::string::npos)
      << slurp(err);
  expectNoFinishedRun(out);
  EXPECT_FALSE(fs::exists(out / "figures" / "error.png"));
  EXPECT_TRUE(processesWorkingIn(out).empty()) << "gnuplot still running";
  fs::remove_all(dir);
}

TEST(StageInterrupt, SigintWhileGnuplotDrawsTheFiguresKillsItAndExitsOneWithinThreeSeconds) {
  interruptWhilePlotting(SIGINT, "int");
}

TEST(StageInterrupt, SigtermWhileGnuplotDrawsTheFiguresKillsItAndExitsOneWithinThreeSeconds) {
  interruptWhilePlotting(SIGTERM, "term");
}

}  // namespace
}  // namespace cosim::test
