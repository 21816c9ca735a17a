// `cosim plan-bench` end to end: ours and OMPL's RRT-Connect on one small world, the files it
// writes (runs.csv, summary.csv, OMPL's benchmark log read the way ompl_benchmark_statistics.py
// reads it, the figure) and its bad-input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "experiments/bench/plan_bench_runs.h"
#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// A 20 x 12 x 6 m room split by a wall with a gap at one end: the straight line from start to
// goal is blocked, so a path must bend around the wall's end.
const char* kWallWorld = R"(world:
  bounds: {min: [0, 0, 0], max: [20, 12, 6]}
  obstacles:
    - {type: box, pos: [10, 5, 3], size: [0.5, 10, 6]}
vehicles:
  - {name: uav1, model: cf2, start: [3, 3, 2], goal: [17, 3, 2]}
planner: {name: rrt_connect, margin: 0.2}
)";
constexpr double kStraightLine = 14.0;
// Around the wall's open end: no path is shorter than the one through its corner (10, 10, 2).
const double kAroundTheWall = 2.0 * std::sqrt(7.0 * 7.0 + 7.0 * 7.0);

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

// One planner's block of an OMPL benchmark log: run property name -> the runs' values.
struct LogPlanner {
  std::string name;
  std::map<std::string, std::string> common;
  std::map<std::string, std::vector<std::string>> columns;
  std::size_t runs = 0;
};

struct ParsedLog {
  std::string version, experiment, host;
  int seed = 0, runs_per_planner = 0;
  double time_limit = 0;
  std::vector<std::string> statuses;
  std::vector<LogPlanner> planners;
};

// Reads the log line by line as ompl_benchmark_statistics.py's readBenchmarkLog does (the same
// token checks), failing the test at the first line that script would reject.
ParsedLog parseOmplLog(const std::string& text) {
  const std::vector<std::string> lines = splitLines(text);
  std::size_t i = 0;
  auto next = [&]() -> const std::string& {
    static const std::string none;
    if (i >= lines.size()) ADD_FAILURE() << "log ends early";
    return i < lines.size() ? lines[i++] : none;
  };
  ParsedLog log;
  auto w = words(next());
  EXPECT_EQ(w.at(1), "version");
  log.version = w.back();
  w = words(next());
  EXPECT_EQ(w.at(0), "Experiment");
  log.experiment = w.back();
  w = words(next());
  EXPECT_EQ(w.at(w.size() - 2), "experiment");
  EXPECT_EQ(w.back(), "properties");
  for (int k = std::stoi(w.at(0)); k > 0; --k)
    EXPECT_NE(next().find(" = "), std::string::npos) << "experiment property";
  w = words(next());
  EXPECT_EQ(w.at(0), "Running");
  log.host = w.back();
  EXPECT_EQ(next().rfind("Starting at ", 0), 0u);
  for (int block = 0; block < 2; ++block) {  // the setup, then the CPU
    EXPECT_EQ(next().rfind("<<<|", 0), 0u);
    while (i < lines.size() && lines[i].rfind("|>>>", 0) != 0) ++i;
    next();
  }
  w = words(next());
  EXPECT_EQ(w.at(w.size() - 2) + " " + w.back(), "random seed");
  log.seed = std::stoi(w.at(0));
  w = words(next());
  EXPECT_EQ(w.back(), "run");
  EXPECT_EQ(w.at(w.size() - 3), "seconds");
  log.time_limit = std::stod(w.at(0));
  w = words(next());
  EXPECT_EQ(w.at(w.size() - 3), "MB");
  w = words(next());
  EXPECT_EQ(w.back(), "planner");
  log.runs_per_planner = std::stoi(w.at(0));
  w = words(next());
  EXPECT_EQ(w.back(), "data");
  w = words(next());
  EXPECT_EQ(w.at(0) + " " + w.back(), "1 type");
  std::istringstream statuses(next());
  for (std::string s; std::getline(statuses, s, '|');) log.statuses.push_back(s);
  EXPECT_EQ(log.statuses.at(0), "status");
  w = words(next());
  EXPECT_EQ(w.back(), "planners");
  for (int p = std::stoi(w.at(0)); p > 0; --p) {
    LogPlanner planner;
    planner.name = next();
    for (int k = std::stoi(words(next()).at(0)); k > 0; --k) {
      const std::string& line = next();
      const auto eq = line.find(" = ");
      EXPECT_NE(eq, std::string::npos) << line;
      planner.common[line.substr(0, eq)] = line.substr(eq + 3);
    }
    std::vector<std::string> names;
    for (int k = std::stoi(words(next()).at(0)); k > 0; --k) {
      const std::string& line = next();
      const std::string type = words(line).back();
      EXPECT_TRUE(type == "REAL" || type == "INTEGER" || type == "BOOLEAN" || type == "ENUM")
          << line;
      names.push_back(line);
    }
    planner.runs = std::stoul(words(next()).at(0));
    for (std::size_t r = 0; r < planner.runs; ++r) {
      std::string line = next();
      std::vector<std::string> values;
      for (std::size_t at; (at = line.find("; ")) != std::string::npos; line.erase(0, at + 2))
        values.push_back(line.substr(0, at));
      EXPECT_EQ(line, "") << "a run's last value is followed by '; '";
      EXPECT_EQ(values.size(), names.size());
      for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
        planner.columns[names[k]].push_back(values[k]);
    }
    EXPECT_EQ(next(), ".");
    log.planners.push_back(planner);
  }
  EXPECT_EQ(i, lines.size()) << "text after the last planner";
  return log;
}

class PlanBench : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(std::string("plan-bench-") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "wall.yaml") << kWallWorld;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string scenario() const { return (dir_ / "wall.yaml").string(); }
  fs::path dir_;
};

TEST_F(PlanBench, OursAndOmplsRrtConnectBothCrossTheWallWorldEveryRun) {
  const fs::path out = dir_ / "out";
  const CommandResult r = runCosim("plan-bench " + scenario() +
                                   " --planners rrt_connect,ompl_rrt_connect --runs 4 --time 2 "
                                   "--out " +
                                   out.string());
  ASSERT_EQ(r.status, 0) << r.err;

  // summary.csv: both solved 4 of 4; lengths at least the straight line, at most twice it.
  const std::vector<std::string> summary = splitLines(slurp(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 3u);
  for (std::size_t k = 1; k < summary.size(); ++k) {
    std::vector<std::string> cell;
    std::istringstream in(summary[k]);
    for (std::string c; std::getline(in, c, ',');) cell.push_back(c);
    ASSERT_EQ(cell.size(), 12u) << summary[k];
    EXPECT_EQ(cell[0], k == 1 ? "rrt_connect" : "ompl_rrt_connect");
    EXPECT_EQ(cell[2], "4");
    EXPECT_EQ(cell[3], "4") << cell[0] << " solved";
    const double shortest = std::stod(cell[11]), q3 = std::stod(cell[10]);
    EXPECT_GE(shortest, kAroundTheWall) << cell[0];
    EXPECT_LE(q3, 3.0 * kStraightLine) << cell[0];
  }

  // The log: what ompl_benchmark_statistics.py reads, with one row per run and both planners.
  const ParsedLog log = parseOmplLog(slurp(out / "plan-bench.log"));
  EXPECT_EQ(log.version, "1.5.2");
  EXPECT_EQ(log.experiment, "cosim-plan-bench");
  EXPECT_EQ(log.runs_per_planner, 4);
  EXPECT_DOUBLE_EQ(log.time_limit, 2.0);
  ASSERT_EQ(log.statuses.size(), 10u);  // "status" and OMPL 1.5's words for its 9 values
  EXPECT_EQ(log.statuses.at(7), "Exact solution");
  ASSERT_EQ(log.planners.size(), 2u);
  EXPECT_EQ(log.planners[0].name, "rrt_connect");
  EXPECT_EQ(log.planners[1].name, "ompl_rrt_connect");
  EXPECT_EQ(log.planners[1].common.at("range"), "2");
  EXPECT_EQ(log.planners[0].common.at("step"), "2");
  for (const LogPlanner& p : log.planners) {
    EXPECT_EQ(p.runs, 4u);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(p.columns.at("solved BOOLEAN").at(k), "1") << p.name;
      EXPECT_EQ(p.columns.at("status ENUM").at(k), "6") << p.name;  // EXACT_SOLUTION
      EXPECT_EQ(p.columns.at("correct solution BOOLEAN").at(k), "1") << p.name;
      EXPECT_EQ(p.columns.at("seed INTEGER").at(k), std::to_string(k + 1));
      const double length = std::stod(p.columns.at("solution length REAL").at(k));
      EXPECT_GE(length, kAroundTheWall);
      const double time = std::stod(p.columns.at("time REAL").at(k));
      EXPECT_GT(time, 0.0);
      EXPECT_LT(time, 2.5);
    }
  }
  // runs.csv: a header and one row per run; the figure in both formats.
  EXPECT_EQ(splitLines(slurp(out / "runs.csv")).size(), 9u);
  EXPECT_GT(fs::file_size(out / "plan_bench.png"), 10000u);
  EXPECT_TRUE(fs::exists(out / "plan_bench.svg"));
  EXPECT_NE(slurp(out / "summary.md").find("| ompl_rrt_connect | OMPL | 4/4 | 100 |"),
            std::string::npos);
}

TEST_F(PlanBench, BadInputIsOneLineExitTwoAndWritesNothing) {
  const fs::path out = dir_ / "out";
  const std::string tail = " --out " + out.string();
  struct Case {
    std::string args, message;
  };
  for (const Case& c : std::vector<Case>{
           {"--planners rrt_conect,ompl_prm --runs 2 --time 1", "did you mean 'rrt_connect'?"},
           {"--planners ompl_rrtconnect --runs 2 --time 1", "did you mean 'ompl_rrt_connect'?"},
           {"--planners rrt,rrt --runs 2 --time 1", "'rrt' is named twice"},
           {"--planners rrt --runs 0 --time 1", "--runs"},
           {"--planners rrt --runs 2 --time 0", "--time"},
           {"--planners rrt --runs 2 --time -1", "--time"},
           {"--planners prm --runs 2 --time 1 --set planner.k=x", "planner.k"}}) {
    const CommandResult r = runCosim("plan-bench " + scenario() + " " + c.args + tail);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(splitLines(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}

TEST(PlanBenchSummary, QuantilesInterpolateBetweenOrderStatistics) {
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.25), 1.75);
  EXPECT_DOUBLE_EQ(quantile({4, 1, 3, 2}, 0.75), 3.25);
  EXPECT_DOUBLE_EQ(quantile({7}, 0.75), 7.0);
  EXPECT_DOUBLE_EQ(quantile({5, 9}, 0.0), 5.0);
}

}  // namespace
}  // namespace cosim::test
