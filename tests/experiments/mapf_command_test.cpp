// End-to-end tests of `cosim mapf` and the seed-004 reproductions / bench section (quick modes).
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <vector>

#include "experiments/bench/mapf_planners.h"
#include "experiments/reproduce/reproduction.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::reproduce {
Report seed004Planners(const Options& options);
Report seed004WhcaWindow(const Options& options);
Report seed004MapfScaling(const Options& options);
}  // namespace cosim::reproduce

using namespace cosim;
using cosim::test::runCosim;

namespace {
const std::string kMap = COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10.map";
const std::string kScen = COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10-random-1.scen";

// Rows of paths.csv per agent, and whether consecutive rows of an agent count t up from 0.
std::vector<int> rowsPerAgent(const std::string& csv, int agents, bool* times_consecutive) {
  std::vector<int> rows(agents, 0);
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  *times_consecutive = true;
  while (std::getline(in, line)) {
    int a = 0, t = 0, x = 0, y = 0;
    char c1, c2, c3;
    std::istringstream l(line);
    l >> a >> c1 >> t >> c2 >> x >> c3 >> y;
    if (t != rows.at(a)) *times_consecutive = false;
    ++rows.at(a);
  }
  return rows;
}
}  // namespace

TEST(MapfCommand, CbsWritesAValidatedSolutionWithOneRowPerAgentPerStep) {
  const auto dir = test::freshDir("mapf-cbs");
  const auto r =
      runCosim("mapf " + kMap + " " + kScen + " --agents 10 --planner cbs --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = test::slurp(dir / "mapf.json");
  EXPECT_TRUE(test::jsonTrue(json, "success"));
  EXPECT_EQ(test::jsonNumber(json, "conflicts"), 0);
  EXPECT_EQ(test::jsonNumber(json, "agents"), 10);
  const std::string csv = test::slurp(dir / "paths.csv");
  EXPECT_EQ(csv.rfind("agent,t,x,y\n", 0), 0u);
  bool consecutive = false;
  const auto rows = rowsPerAgent(csv, 10, &consecutive);
  EXPECT_TRUE(consecutive);
  long soc = 0;
  int longest = 0;
  for (const int n : rows) soc += n - 1, longest = std::max(longest, n - 1);
  // Rows run from t = 0 to each agent's arrival, so they add up to the reported costs.
  EXPECT_EQ(test::jsonNumber(json, "sum_of_costs"), soc);
  EXPECT_EQ(test::jsonNumber(json, "makespan"), longest);
  std::filesystem::remove_all(dir);
}

TEST(MapfCommand, ExitCodesForFailureAndBadInput) {
  const auto dir = test::freshDir("mapf-codes");
  const std::string base = "mapf " + kMap + " " + kScen + " --out " + dir.string();
  // Independent A* paths conflict on 30 agents: planning failed, not bad input.
  EXPECT_EQ(runCosim(base + " --agents 30 --planner independent_astar").status, 1);
  const auto too_many = runCosim(base + " --agents 5000 --planner cbs");
  EXPECT_EQ(too_many.status, 2);
  EXPECT_NE(too_many.err.find("scenario lines"), std::string::npos);
  EXPECT_EQ(runCosim(base + " --agents 5 --planner astar").status, 2);
  EXPECT_EQ(runCosim(base + " --agents 5 --planner cbs --window 4").status, 2);
  EXPECT_EQ(runCosim(base + " --agents 5 --planner whca_star --connectivity 6").status, 2);
  EXPECT_EQ(runCosim(base + " --agents 5 --planner whca_star --window 4 --connectivity 8").status,
            0);
  std::filesystem::remove_all(dir);
}

TEST(Seed004Reproductions, QuickRunsProduceTheirTables) {
  reproduce::Options o;
  o.quick = true;
  const std::string planners = reproduce::seed004Planners(o).markdown;
  EXPECT_NE(planners.find("| maze | 5 | CBS (optimal) | 100 |"), std::string::npos) << planners;
  EXPECT_NE(planners.find("no numeric results"), std::string::npos);
  const std::string window = reproduce::seed004WhcaWindow(o).markdown;
  EXPECT_NE(window.find("| bottleneck | 5 | dynamic (window widened up to max(w, 5)) |"),
            std::string::npos)
      << window;
  const std::string scaling = reproduce::seed004MapfScaling(o).markdown;
  EXPECT_NE(scaling.find("| empty-8-8 | 5 | 1 | 100 |"), std::string::npos) << scaling;
}

TEST(MapfBench, QuickSectionReportsBothPlannersAtTwentyAgents) {
  const bench::Section s = bench::benchMapfPlanners(true);
  int found = 0;
  for (const auto& f : s.figures) {
    if (f.name == "cbs_ms_random32_20" || f.name == "whca_ms_random32_20") {
      ++found;
      EXPECT_GT(f.value, 0.0);
    }
  }
  EXPECT_EQ(found, 2);
}

// The plan driven by ground robots in MuJoCo: every robot arrives, no robot touches another or a
// block, and the execution's scenario (written next to the results) is the map with its cells.
TEST(MapfCommand, ExecuteDrivesTheCbsPlanWithRobotsInPhysicsWithoutContacts) {
  const auto dir = test::freshDir("mapf-execute");
  const std::string map = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map";
  const std::string scen = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8-random-1.scen";
  const auto r =
      runCosim("mapf " + map + " " + scen +
               " --agents 6 --planner cbs --block 3,3 --block 4,3 --execute --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string planned = test::slurp(dir / "mapf.json");
  const std::string run = test::slurp(dir / "execution" / "metrics.json");
  ASSERT_FALSE(run.empty()) << r.err;
  EXPECT_TRUE(test::jsonTrue(run, "reached_goal"));
  EXPECT_EQ(test::jsonNumber(run, "robots"), 6);
  EXPECT_EQ(test::jsonNumber(run, "robot_contacts"), 0);
  EXPECT_EQ(test::jsonNumber(run, "obstacle_contacts"), 0);
  // The physics ran the same plan: its step count times the step time is the planned makespan
  // (one step of settling and one onto the goal point aside).
  const double step = test::jsonNumber(run, "planner_counters.step_time_s");
  EXPECT_NEAR(test::jsonNumber(run, "planned_makespan_s"),
              test::jsonNumber(planned, "makespan") * step + 0.2, 1.01 * step);
  // The very plan mapf.json describes, not a second search: its search time is the run's
  // planning time to the last digit (JSON doubles round-trip), which no new search repeats.
  EXPECT_EQ(test::jsonNumber(run, "planning_time_ms"), test::jsonNumber(planned, "time_ms"));
  // Followed within a fraction of the 0.5 m cell.
  EXPECT_LT(test::jsonNumber(run, "max_error_m"), 0.1);
  // The user's blocks are in the scenario, which `cosim run` can run again.
  const std::string yaml = test::slurp(dir / "execution" / "scenario.yaml");
  EXPECT_NE(yaml.find("blocked"), std::string::npos);
  EXPECT_NE(yaml.find("[4, 3]"), std::string::npos);
  EXPECT_NE(r.out.find("6/6 robots arrived, 0 contacts"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

// Robots too wide for the cells are bad input found before planning: exit 2, nothing written.
TEST(MapfCommand, ExecuteRefusesCellsTooSmallForTheRobotBeforePlanning) {
  const auto dir = test::freshDir("mapf-execute-small-cells");
  const auto r =
      runCosim("mapf " COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map " COSIM_SOURCE_DIR
               "/experiments/maps/empty-8-8-random-1.scen --agents 4 --planner cbs --execute "
               "--connectivity 8 --cell 0.5 --out " +
               dir.string());
  EXPECT_EQ(r.status, 2);
  // omni_base (radius 0.15 m) plus the 0.05 m margin needs 0.2 / (sqrt(2) / 4) = 0.566 m cells.
  EXPECT_NE(r.err.find("need cells of at least 0.565685 m"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir));
}

// The benchmark form: every planner at every count; one CSV row per planner and count, the
// success-rate figure and the summary with the published LaCAM* figures beside ours.
TEST(MapfCommand, AgentRangeRunsEveryPlannerAtEveryCountAndWritesCsvFigureAndSummary) {
  const auto dir = test::freshDir("mapf-benchmark");
  const std::string map = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8.map";
  const std::string scen = COSIM_SOURCE_DIR "/experiments/maps/empty-8-8-random-1.scen";
  const auto r =
      runCosim("mapf " + map + " " + scen +
               " --agents 4:12:4 --planner lacam,pibt,cbs --time-limit 5 --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = test::slurp(dir / "benchmark.csv");
  EXPECT_EQ(csv.rfind("map,scen,planner,agents,status,success,sum_of_costs,makespan,time_ms,"
                      "first_solution_ms,first_cost,final_cost,conflicts,table_mb,peak_rss_mb,"
                      "message\n",
                      0),
            0u);
  std::istringstream rows(csv);
  std::string line;
  std::getline(rows, line);
  int n = 0, lacam_solved = 0;
  std::map<int, long> cbs_soc, lacam_soc;
  while (std::getline(rows, line)) {
    ++n;
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
    ASSERT_GE(f.size(), 15u) << line;
    const int agents = std::stoi(f[3]);
    EXPECT_EQ(f[12], "0") << line;  // no conflicts in anything returned
    // Memory: the process holds at least its own code; pibt's distance tables hold at most a
    // row of 64 two-byte cells and a frontier per agent (12 x 192 bytes: under 0.01 MB).
    EXPECT_GT(std::stod(f[14]), 1.0) << line;
    if (f[2] == "pibt") {
      EXPECT_LE(std::stod(f[13]), 0.01) << line;
      if (f[5] == "1") {
        EXPECT_EQ(f[9], f[8]) << line;  // its one solution is its first
      }
    }
    if (f[2] == "lacam") {
      EXPECT_GT(std::stod(f[13]), 0.0) << line;
    }
    if (f[2] == "cbs" && f[5] == "1") cbs_soc[agents] = std::stol(f[6]);
    if (f[2] == "lacam") {
      ASSERT_EQ(f[5], "1") << line;
      ++lacam_solved;
      lacam_soc[agents] = std::stol(f[6]);
      // First and final cost of the anytime search; the final one is the reported SOC.
      EXPECT_GE(std::stol(f[10]), std::stol(f[11])) << line;
      EXPECT_EQ(f[11], f[6]) << line;
    }
  }
  EXPECT_EQ(n, 9);  // 3 planners x 3 counts
  EXPECT_EQ(lacam_solved, 3);
  for (const auto& [agents, soc] : cbs_soc) EXPECT_LE(soc, lacam_soc.at(agents)) << agents;
  EXPECT_TRUE(std::filesystem::file_size(dir / "success_rate.png") > 1000);
  EXPECT_TRUE(std::filesystem::exists(dir / "success_rate.svg"));
  EXPECT_NE(test::slurp(dir / "success_rate.csv").find("lacam,12,1,1,100.0"), std::string::npos);
  const std::string md = test::slurp(dir / "benchmark.md");
  EXPECT_NE(md.find("## Published: LaCAM* (Okumura, IJCAI 2023, Fig. 1)"), std::string::npos);
  EXPECT_NE(md.find("`empty-8-8` is one of those 33 maps"), std::string::npos);
  EXPECT_NE(md.find("| 12 | 100 | 100 |"), std::string::npos) << md;
  // Progress on stderr, one line per run.
  EXPECT_NE(r.err.find("[9/9] cbs, 12 agents"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

TEST(MapfCommand, BadAgentRangesAndBenchmarkOptionsAreExitTwo) {
  const auto dir = test::freshDir("mapf-benchmark-bad");
  const std::string base = "mapf " + kMap + " " + kScen + " --out " + dir.string();
  for (const std::string bad :
       {"--agents 10:5:1 --planner lacam", "--agents 1:x:2 --planner lacam",
        "--agents 0:10:2 --planner lacam", "--agents 2:10 --planner lacam",
        "--agents 2:10:2 --planner lacam,teleport", "--agents 2:10:2 --planner lacam,,cbs",
        "--agents 2:10:2 --planner lacam --execute",
        "--agents 2:10:2 --planner lacam,cbs --set astar.x=1",
        "--agents 2:10:2 --planner lacam,cbs --set anytime=false"}) {
    const auto r = runCosim(base + " " + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.err;
    EXPECT_NE(r.err.find("cosim: "), std::string::npos) << bad;
    EXPECT_FALSE(std::filesystem::exists(dir)) << bad;  // nothing created
  }
  // A planner-only parameter is fine.
  EXPECT_EQ(runCosim(base + " --agents 2:4:2 --planner lacam,cbs --set lacam.anytime=false").status,
            0);
  std::filesystem::remove_all(dir);
}
