// `cosim sweep` end to end on an 8-job sweep of small generated worlds: one row per job in id
// order, nothing re-run on a second invocation, shards that merge to the same table as one run
// (with a different --jobs), located bad-input errors (exit 2), and a clean stop on SIGINT that a
// re-run completes without duplicated or truncated rows.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "tests/support/cosim_command.h"

namespace cosim {
namespace {

namespace fs = std::filesystem;
using test::runCosim;
using test::slurp;

const char* kSweep = R"(# 2 worlds x 2 planners x 2 seeds
generators:
  - {type: city, density: 0.5, size: [16, 16, 5], seed: 1}
  - {type: maze, density: 1.0, size: [12, 12, 3], cell: 3, seed: 2}
vary:
  planner.name: [astar, theta_star]
  sim.seed: [1, 2]
set: {sim.max_time: 30}
output: {video: false}
limits: {job_timeout_s: 120}
)";

// RFC 4180 fields of one CSV line (quoted fields may hold commas).
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      out.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(slurp(p));
  for (std::string line; std::getline(in, line);) rows.push_back(csvFields(line));
  return rows;
}

// Columns measured by a clock differ between runs; everything else must match.
bool wallClockColumn(const std::string& name) {
  return name.find("time_ms") != std::string::npos || name.find("wall") != std::string::npos ||
         name == "sim_speed_x";
}

// Each test has its own folder (CTest runs every test in a process of its own).
class SweepCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::freshDir(std::string("sweep-cli-") +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_);
    std::ofstream(root_ / "small.yaml") << kSweep;
  }
  void TearDown() override { fs::remove_all(root_); }
  test::CommandResult sweep(const std::string& args) {
    return runCosim("sweep " + (root_ / "small.yaml").string() + " " + args);
  }
  fs::path root_;
};

TEST_F(SweepCommandTest, RunsEveryJobInIdOrderAndASecondInvocationDoesNoWork) {
  const auto first = sweep("--jobs 2 --out " + (root_ / "a").string());
  ASSERT_EQ(first.status, 0) << first.err;
  EXPECT_NE(first.err.find("8/8 done (8 ok)"), std::string::npos) << first.err;
  const auto rows = readCsv(root_ / "a/results.csv");
  ASSERT_EQ(rows.size(), 9u);
  const std::vector<std::string> start(rows[0].begin(), rows[0].begin() + 6);
  EXPECT_EQ(start, (std::vector<std::string>{"job", "scenario", "planner.name", "sim.seed",
                                             "status", "reached_goal"}));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].size(), rows[0].size());
    EXPECT_EQ(rows[i][0], std::to_string(i - 1));
    EXPECT_EQ(rows[i][4], "ok") << "job " << i - 1 << ": "
                                << slurp(root_ /
                                         ("a/jobs/000" + std::to_string(i - 1) + "/log.txt"));
  }
  EXPECT_EQ(rows[1][1], "worlds/city-d0.5-s1-16x16x5.yaml");
  EXPECT_EQ(rows[8][1], "worlds/maze-d1-s2-12x12x3.yaml");
  EXPECT_EQ(rows[8][2], "theta_star");
  EXPECT_EQ(rows[8][3], "2");
  // summary.csv: 2 worlds x 2 planners, seeds pooled; ok_rate first.
  int ok_rows = 0;
  for (const auto& r : readCsv(root_ / "a/summary.csv"))
    if (r.size() > 4 && r[2] == "ok_rate") {
      ++ok_rows;
      EXPECT_EQ(r[3], "2");  // jobs
      EXPECT_EQ(r[5], "1");  // mean
    }
  EXPECT_EQ(ok_rows, 4);
  EXPECT_TRUE(fs::exists(root_ / "a/figure.png"));

  const std::string before = slurp(root_ / "a/results.csv");
  const auto again = sweep("--out " + (root_ / "a").string());
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.err.find("8 jobs, 8 already finished, 0 to run"), std::string::npos) << again.err;
  EXPECT_EQ(slurp(root_ / "a/results.csv"), before);
}

TEST_F(SweepCommandTest, TwoShardsMergedEqualOneRunRowForRow) {
  const auto whole = sweep("--jobs 2 --out " + (root_ / "a").string());
  ASSERT_EQ(whole.status, 0) << whole.err;
  const std::string out = (root_ / "b").string();
  for (const char* shard : {"1/2", "2/2"}) {
    const auto r = sweep(std::string("--jobs 1 --shard ") + shard + " --out " + out);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("4 jobs, 0 already finished, 4 to run"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(root_ / "b/results.csv"));  // shards leave the merge to --merge-only
  const auto merged = sweep("--merge-only --out " + out);
  ASSERT_EQ(merged.status, 0) << merged.err;
  const auto a = readCsv(root_ / "a/results.csv"), b = readCsv(root_ / "b/results.csv");
  ASSERT_EQ(a.size(), 9u);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a[0], b[0]);
  int compared = 0;
  for (std::size_t i = 1; i < a.size(); ++i)
    for (std::size_t c = 0; c < a[0].size(); ++c) {
      if (wallClockColumn(a[0][c])) continue;
      EXPECT_EQ(a[i][c], b[i][c]) << "row " << i << ", column " << a[0][c];
      ++compared;
    }
  EXPECT_GT(compared, 8 * 30);
}

TEST_F(SweepCommandTest, AMalformedSweepFileOrAnUnknownKeyExitsTwoNamingFileLineAndKey) {
  const fs::path bad = root_ / "bad.yaml";
  std::ofstream(bad) << "generators: [{type: city, size: [16, 16, 5]}]\nvary:\n  planner.name: "
                        "[astar]\n  sim.sed: [1]\n";
  auto r = runCosim("sweep " + bad.string() + " --out " + (root_ / "bad").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err.rfind("cosim: " + bad.string() + ": line 4, key vary.sim.sed: scenario worlds/", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("unknown key 'sed'"), std::string::npos) << r.err;
  std::ofstream(bad) << "generators: [{type: city}]\nvary: {planner.name: [astar}\n";
  r = runCosim("sweep " + bad.string() + " --out " + (root_ / "bad").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.rfind("cosim: " + bad.string() + ": line 2: malformed YAML", 0), 0u) << r.err;
  r = runCosim("sweep " + (root_ / "small.yaml").string() + " --shard 3/2 --out " +
               (root_ / "bad").string());
  EXPECT_EQ(r.status, 2);
}

TEST_F(SweepCommandTest, AnInterruptedSweepResumesWithoutDuplicatedOrTruncatedRows) {
  const fs::path out = root_ / "c";
  const std::string sweep_file = (root_ / "small.yaml").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string log = (root_ / "c.log").string();
    std::freopen(log.c_str(), "w", stderr);
    std::freopen("/dev/null", "w", stdout);
    ::execl(COSIM_BINARY, COSIM_BINARY, "sweep", sweep_file.c_str(), "--jobs", "1", "--out",
            out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Interrupt once the first job has finished and the second is under way.
  const auto t0 = std::chrono::steady_clock::now();
  while (!fs::exists(out / "jobs/0001/log.txt") &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(90))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << slurp(root_ / "c.log");
  EXPECT_NE(slurp(root_ / "c.log").find("interrupted"), std::string::npos);
  // Nothing half-done looks finished: the tables of the jobs that finished are .partial, and the
  // sweep's state and manifest say how far it got.
  EXPECT_FALSE(fs::exists(out / "results.csv"));
  EXPECT_FALSE(fs::exists(out / "summary.csv"));
  EXPECT_FALSE(fs::exists(out / "figure.png"));
  auto rows = readCsv(out / "results.partial.csv");
  ASSERT_GE(rows.size(), 2u);  // the first job, at least
  EXPECT_LT(rows.size(), 9u);  // not all of them
  for (const auto& r : rows) EXPECT_EQ(r.size(), rows[0].size());
  const std::string state = "partial: " + std::to_string(rows.size() - 1) + " of 8 jobs";
  EXPECT_NE(slurp(out / "sweep-state.json").find("\"state\": \"" + state + "\""), std::string::npos)
      << slurp(out / "sweep-state.json");
  EXPECT_NE(slurp(out / ".cosim-manifest").find(state), std::string::npos);

  const auto resumed = sweep("--jobs 2 --out " + out.string());
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  // The count of ok jobs includes those the first invocation finished, as "done" does.
  EXPECT_NE(resumed.err.find("8/8 done (8 ok)"), std::string::npos) << resumed.err;
  rows = readCsv(out / "results.csv");
  ASSERT_EQ(rows.size(), 9u);
  std::set<std::string> ids;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].size(), rows[0].size());
    EXPECT_EQ(rows[i][4], "ok");
    ids.insert(rows[i][0]);
  }
  EXPECT_EQ(ids.size(), 8u);
  EXPECT_FALSE(fs::exists(out / "results.partial.csv"));
  EXPECT_NE(slurp(out / "sweep-state.json").find("\"state\": \"complete\""), std::string::npos);
}

// A sweep with another grid into a finished sweep's folder is refused before anything in it
// changes: its tables, job folders and worlds stay the first sweep's.
TEST_F(SweepCommandTest, AnotherSweepIntoAFinishedSweepsFolderIsRefused) {
  const fs::path one = root_ / "one.yaml", other = root_ / "other.yaml";
  const char* kOne =
      "generators: [{type: city, density: 0.5, size: [16, 16, 5], seed: 1}]\n"
      "vary: {planner.name: [astar]}\nset: {sim.max_time: 30}\noutput: {video: false}\n";
  std::ofstream(one) << kOne;
  std::ofstream(other) << "name: one\n"
                       << "generators: [{type: city, density: 0.5, size: [16, 16, 5], seed: 2}]\n"
                       << "vary: {planner.name: [astar]}\nset: {sim.max_time: 30}\n"
                       << "output: {video: false}\n";
  const fs::path out = root_ / "s";
  const auto first = runCosim("sweep " + one.string() + " --out " + out.string());
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string results = slurp(out / "results.csv");

  const auto refused = runCosim("sweep " + other.string() + " --out " + out.string());
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_NE(refused.err.find(out.string() + ": --out: holds another sweep ('one'"),
            std::string::npos)
      << refused.err;
  EXPECT_EQ(slurp(out / "results.csv"), results);
  EXPECT_EQ(slurp(out / "sweep.yaml"), kOne);
  EXPECT_FALSE(fs::exists(out / "worlds/city-d0.5-s2-16x16x5.yaml"));

  // The same sweep again (its text edited, its grid the same) is not another sweep.
  std::ofstream(one, std::ios::app) << "# a comment\n";
  const auto again = runCosim("sweep " + one.string() + " --out " + out.string());
  EXPECT_EQ(again.status, 0) << again.err;
}

}  // namespace
}  // namespace cosim

namespace cosim {
namespace {

// A sweep naming the bundled forest and canyon scenarios (paths relative to
// the project); with one planner and one seed it is two jobs, both flown to the goal.
TEST(SweepContractExample, TheContractsForestAndCanyonExampleRunsFromTheProjectFolder) {
  const fs::path dir = test::freshDir("sweep-contract-example");
  fs::create_directories(dir);
  std::ofstream(dir / "example.yaml")
      << "scenarios: [experiments/scenarios/forest.yaml, experiments/scenarios/canyon.yaml]\n"
         "vary:\n  planner.name: [theta_star]\n  sim.seed: [1]\noutput: {video: false}\n";
  const auto r = runCosim(
      "sweep " + (dir / "example.yaml").string() + " --out " + (dir / "out").string() + " --quiet",
      COSIM_SOURCE_DIR);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(dir / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const auto& header = rows[0];
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  for (int job = 1; job <= 2; ++job) {
    EXPECT_EQ(rows[job].at(column("status")), "ok");
    EXPECT_EQ(rows[job].at(column("reached_goal")), "true");
    EXPECT_EQ(rows[job].at(column("collisions")), "0");
  }
  EXPECT_EQ(rows[2].at(column("scenario")), "experiments/scenarios/canyon.yaml");
  fs::remove_all(dir);
}

// The bundled team scenario sweeps like `cosim run` runs it (its validation used to know only
// the single-agent planners: "unknown planner 'cbs'", exit 2). Short flights keep it quick.
TEST(SweepGroundTeam, TheBundledGroundTeamScenarioSweeps) {
  const fs::path dir = test::freshDir("sweep-ground-team");
  fs::create_directories(dir);
  std::ofstream(dir / "team.yaml") << "scenarios: [experiments/scenarios/ground_team.yaml]\n"
                                      "vary: {planner.name: [cbs, whca_star]}\n"
                                      "set: {sim.max_time: 3}\noutput: {video: false}\n";
  const auto r = runCosim(
      "sweep " + (dir / "team.yaml").string() + " --out " + (dir / "out").string() + " --quiet",
      COSIM_SOURCE_DIR);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(dir / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const auto status = static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), "status") -
                                               rows[0].begin());
  // 3 s is too short to arrive: the runs completed and failed their task, as `cosim run` says.
  for (int job = 1; job <= 2; ++job) EXPECT_EQ(rows[job].at(status), "failed") << r.err;
  fs::remove_all(dir);
}

// A sweep resumed after a file its scenario includes changed reruns the job (the old result
// showed 0 collisions where a fresh run has them), and one resumed without changes runs nothing.
TEST(SweepResume, AJobWhoseIncludedFragmentChangedRunsAgain) {
  const fs::path dir = test::freshDir("sweep-include-changed");
  fs::create_directories(dir);
  std::ofstream(dir / "frag.xml") << "<mujoco><worldbody/></mujoco>\n";
  std::ofstream(dir / "s.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}, include: frag.xml}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [8, 2, 1]}]\n"
         "sim: {max_time: 10}\n";
  std::ofstream(dir / "sweep.yaml") << "scenarios: [s.yaml]\noutput: {video: false}\n";
  const std::string cmd =
      "sweep " + (dir / "sweep.yaml").string() + " --out " + (dir / "out").string();
  const auto first = runCosim(cmd);
  ASSERT_EQ(first.status, 0) << first.err;
  const auto column = [](const std::vector<std::vector<std::string>>& rows,
                         const std::string& name) {
    return rows.at(1).at(static_cast<std::size_t>(std::find(rows[0].begin(), rows[0].end(), name) -
                                                  rows[0].begin()));
  };
  EXPECT_EQ(column(readCsv(dir / "out" / "results.csv"), "collisions"), "0");

  const auto unchanged = runCosim(cmd);
  EXPECT_NE(unchanged.err.find("1 jobs, 1 already finished, 0 to run"), std::string::npos)
      << unchanged.err;

  // A wall across the straight flight: the same scenario text now collides.
  std::ofstream(dir / "frag.xml")
      << "<mujoco><worldbody><geom type=\"box\" pos=\"5 2 1\" size=\"0.2 3 2\"/>"
         "</worldbody></mujoco>\n";
  const auto resumed = runCosim(cmd);
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("1 jobs, 0 already finished, 1 to run"), std::string::npos)
      << resumed.err;
  const auto rows = readCsv(dir / "out" / "results.csv");
  EXPECT_NE(column(rows, "collisions"), "0");
  EXPECT_EQ(column(rows, "status"), "failed");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim
