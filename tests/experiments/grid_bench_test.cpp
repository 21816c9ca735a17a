// `cosim grid-bench` end to end (the built program), plus the grid A*-vs-Boost bench section and
// the seed-003 discrete reproduction in their quick modes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/bench/grid_astar_vs_boost.h"
#include "experiments/reproduce/reproduction.h"
#include "tests/support/test_files.h"

namespace cosim::reproduce {
Report seed003Discrete(const Options& options);
}

namespace {

namespace fs = std::filesystem;

// MovingAI files: the grid tests' own, and those cosim bundles.
const std::string kData = COSIM_TEST_DATA_DIR "/movingai/";
const std::string kMaps = COSIM_SOURCE_DIR "/experiments/maps/";

struct CommandRun {
  int status;
  std::string out, err;
};

using cosim::test::slurp;

class GridBenchCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        cosim::test::makeFreshDir(std::string("grid-bench-") +
                                  ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

  CommandRun run(const std::string& args) {
    const std::string cmd = std::string(COSIM_BINARY) + " grid-bench " + args + " >" +
                            (dir_ / "stdout").string() + " 2>" + (dir_ / "stderr").string();
    const int raw = std::system(cmd.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir_ / "stdout"), slurp(dir_ / "stderr")};
  }

  static std::vector<std::vector<std::string>> csvRows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
      std::vector<std::string> fields;
      std::string f;
      std::istringstream l(line);
      while (std::getline(l, f, ',')) fields.push_back(f);
      if (!line.empty() && line.back() == ',') fields.push_back("");
      rows.push_back(fields);
    }
    return rows;
  }

  fs::path dir_;
};

}  // namespace

TEST_F(GridBenchCommand, AStarOnArenaWritesTheContractCsvAndMatchesEveryOptimum) {
  const fs::path csv = dir_ / "arena.csv";
  const CommandRun r =
      run(kData + "arena.map " + kData + "arena.map.scen --planner astar --out " + csv.string());
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  const auto rows = csvRows(slurp(csv));
  ASSERT_EQ(rows.size(), 161u);  // header + 160 scenario lines
  const std::vector<std::string> contract = {"id",      "start_x", "start_y", "goal_x",    "goal_y",
                                             "optimal", "length",  "time_us", "expansions"};
  EXPECT_EQ(std::vector<std::string>(rows[0].begin(), rows[0].begin() + 9), contract);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double optimal = std::stod(rows[i][5]), length = std::stod(rows[i][6]);
    EXPECT_NEAR(length, optimal, 1e-4 * std::max(1.0, optimal)) << "row " << i;
  }
  EXPECT_NE(r.out.find("solved:     160"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("mismatches: 0"), std::string::npos) << r.out;
}

TEST_F(GridBenchCommand, LimitPlansOnlyTheFirstLines) {
  const fs::path csv = dir_ / "maze.csv";
  const CommandRun r =
      run(kMaps + "maze-32-32-2.map " + kMaps +
          "maze-32-32-2-random-1.scen --planner bellman_ford --limit 7 --out " + csv.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(csvRows(slurp(csv)).size(), 8u);
  EXPECT_NE(r.out.find("lines:      7"), std::string::npos) << r.out;
}

TEST_F(GridBenchCommand, AnyAnglePlannerIsNotHeldToTheOctileOptimum) {
  const CommandRun r = run(kData + "arena.map " + kData + "arena.map.scen --planner theta_star");
  EXPECT_EQ(r.status, 0) << r.err;
  // Theta* beats the octile optimum on most open-arena lines, so mismatches are many.
  EXPECT_EQ(r.out.find("mismatches: 0 "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not held to the optimum"), std::string::npos) << r.out;
}

TEST_F(GridBenchCommand, UnreachableGoalAndBlockedStartFailTheirLinesWithExit1) {
  const fs::path map =
      write("wall.map", "type octile\nheight 3\nwidth 5\nmap\n..@..\n..@..\n..@..\n");
  const fs::path scen = write("wall.map.scen",
                              "version 1\n0\twall.map\t5\t3\t0\t0\t1\t1\t1.41421356\n"
                              "0\twall.map\t5\t3\t0\t0\t4\t2\t5.0\n"
                              "0\twall.map\t5\t3\t2\t1\t0\t0\t2.0\n");
  const fs::path csv = dir_ / "wall.csv";
  const CommandRun r =
      run(map.string() + " " + scen.string() + " --planner dijkstra --out " + csv.string());
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  const std::string text = slurp(csv);
  const auto rows = csvRows(text);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_NEAR(std::stod(rows[1][6]), std::sqrt(2.0), 1e-6);
  EXPECT_EQ(rows[2][6], "");  // no path: length empty
  EXPECT_EQ(rows[2].back(), "no path");
  EXPECT_EQ(rows[3][6], "");
  // The reason contains commas, so it is quoted.
  EXPECT_NE(text.find(",\"start cell (2,1,0) is blocked\"\n"), std::string::npos) << text;
  EXPECT_NE(r.out.find("solved:     1"), std::string::npos) << r.out;
}

TEST_F(GridBenchCommand, MalformedFilesAreExit2WithOneLineNamingTheFile) {
  const fs::path good_scen =
      write("a.map.scen", "version 1\n0\ta.map\t3\t2\t0\t0\t2\t1\t2.41421356\n");
  const fs::path short_row = write("a.map", "type octile\nheight 2\nwidth 3\nmap\n...\n..\n");
  CommandRun r = run(short_row.string() + " " + good_scen.string() + " --planner astar");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("a.map: line 6"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

  const fs::path ok_map = write("b.map", "type octile\nheight 2\nwidth 3\nmap\n...\n...\n");
  const fs::path bad_scen = write("b.map.scen", "version 1\n0\tb.map\t3\t2\t0\tzero\t2\t1\t2.4\n");
  r = run(ok_map.string() + " " + bad_scen.string() + " --planner astar");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("b.map.scen: line 2"), std::string::npos) << r.err;

  // A scenario written for another map size.
  const fs::path other = write("c.map.scen", "version 1\n0\tb.map\t4\t2\t0\t0\t2\t1\t2.4\n");
  r = run(ok_map.string() + " " + other.string() + " --planner astar");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("4x2 map"), std::string::npos) << r.err;
}

TEST_F(GridBenchCommand, HeaderClaimingABillionCellsIsRejectedWithoutAllocating) {
  const fs::path huge = write("huge.map", "type octile\nheight 31623\nwidth 31623\nmap\n....\n");
  const fs::path scen =
      write("huge.map.scen", "version 1\n0\thuge.map\t31623\t31623\t0\t0\t1\t1\t1.4\n");
  const CommandRun r = run(huge.string() + " " + scen.string() + " --planner astar");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("exceeds the grid size limit"), std::string::npos) << r.err;
}

TEST_F(GridBenchCommand, UnknownPlannerOrParameterIsExit2) {
  const std::string files = kData + "arena.map " + kData + "arena.map.scen";
  CommandRun r = run(files + " --planner no_such_planner");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown grid planner 'no_such_planner'"), std::string::npos) << r.err;
  r = run(files + " --planner astar --set conectivity=4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("conectivity"), std::string::npos) << r.err;
  r = run(files + " --planner astar --set connectivity=6");  // a 3D value on a 2D map
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("parameter connectivity"), std::string::npos) << r.err;
}

TEST_F(GridBenchCommand, FourConnectedAStarIsLongerAndFailsTheOptimumCheck) {
  const CommandRun r = run(kData + "arena.map " + kData +
                           "arena.map.scen --planner astar --limit 40 " + "--set connectivity=4");
  // 4-connected A* is not held to the 8-connected optimum, so the exit status stays 0, and its
  // Manhattan lengths differ from the octile optimum on the diagonal lines.
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("mismatches: 0 "), std::string::npos) << r.out;
}

TEST(GridAStarVsBoostBench, QuickSectionComparesBothGridsWithIdenticalLengths) {
  const cosim::bench::Section s = cosim::bench::benchGridAStarVsBoost(true);
  std::map<std::string, double> f;
  for (const auto& fig : s.figures) f[fig.name] = fig.value;
  EXPECT_EQ(f.at("map_queries"), 100);
  EXPECT_EQ(f.at("grid3d_queries"), 4);
  EXPECT_EQ(f.at("map_length_mismatches"), 0);
  EXPECT_EQ(f.at("grid3d_length_mismatches"), 0);
  EXPECT_GT(f.at("map_ours_total_ms"), 0);
  EXPECT_GT(f.at("map_boost_total_ms"), 0);
}

TEST(Seed003DiscreteReproduction, QuickRunReportsAllFourTablesWithPaths) {
  cosim::reproduce::Options o;
  o.quick = true;
  const std::string md = cosim::reproduce::seed003Discrete(o).markdown;
  for (const char* t : {"Tab. 1", "Tab. 2", "Tab. 3", "Tab. 4"})
    EXPECT_NE(md.find(t), std::string::npos) << t;
  EXPECT_EQ(md.find("no path"), std::string::npos);
  // The seed's published Basic Theta* length on the 2D map appears beside ours.
  EXPECT_NE(md.find("33.6927"), std::string::npos);
}
