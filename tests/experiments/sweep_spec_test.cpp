// Sweep files: the grid they expand to, where their scenario paths point, how they shard, and the
// located errors (file, line, key, problem) that make `cosim sweep` exit 2.
#include "experiments/sweep/sweep_spec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "experiments/sweep/sweep_jobs.h"
#include "experiments/sweep/sweep_shard.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

namespace fs = std::filesystem;

const char* kScenario = R"(world:
  bounds: {min: [0, 0, 0], max: [20, 20, 6]}
  obstacles:
    - {type: box, pos: [10, 10, 3], size: [2, 8, 6]}
vehicles:
  - {name: uav1, model: quad_1500g, start: [2, 2, 2], goal: [18, 18, 2]}
planner: {name: astar, resolution: 0.5}
sim: {max_time: 30, seed: 1}
)";

// A tree: root/scenarios/a.yaml, root/scenarios/b.yaml, root/sweeps/ (sweep files go there).
class SweepSpecTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = cosim::test::freshDir("sweep-spec");
    fs::create_directories(root_ / "scenarios");
    fs::create_directories(root_ / "sweeps");
    write(root_ / "scenarios/a.yaml", kScenario);
    write(root_ / "scenarios/b.yaml", kScenario);
  }
  void TearDown() override { fs::remove_all(root_); }
  static void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
  SweepSpec parse(const std::string& text) { return parseSweepSpec(text, root_ / "sweeps/s.yaml"); }
  // "place | problem" of the InputError that parsing (and validating) `text` throws.
  std::string errorOf(const std::string& text) {
    try {
      const SweepSpec s = parse(text);
      validateSweepJobs(s, expandSweepJobs(s, root_ / "out"));
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), (root_ / "sweeps/s.yaml").string());
      return e.place() + " | " + e.problem();
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return "";
  }
  fs::path root_;
};

TEST_F(SweepSpecTest, EveryCombinationIsOneJobWithTheFirstKeySlowest) {
  const SweepSpec s = parse(
      "scenarios: [../scenarios/a.yaml, ../scenarios/b.yaml]\n"
      "vary:\n  planner.name: [astar, theta_star, lazy_theta_star]\n  sim.seed: [1, 2, 3]\n"
      "output: {video: false}\n");
  const auto jobs = expandSweepJobs(s, root_ / "out");
  ASSERT_EQ(jobs.size(), 18u);
  EXPECT_EQ(jobs[0].scenario, "../scenarios/a.yaml");
  EXPECT_EQ(jobs[0].values, (std::vector<std::string>{"astar", "1"}));
  EXPECT_EQ(jobs[1].values, (std::vector<std::string>{"astar", "2"}));
  EXPECT_EQ(jobs[3].values, (std::vector<std::string>{"theta_star", "1"}));
  EXPECT_EQ(jobs[9].scenario, "../scenarios/b.yaml");
  EXPECT_EQ(jobs[17].id, 17u);
  EXPECT_EQ(jobs[17].overrides,
            (std::vector<std::string>{"planner.name=lazy_theta_star", "sim.seed=3"}));
  EXPECT_NO_THROW(validateSweepJobs(s, jobs));
}

TEST_F(SweepSpecTest, FixedOverridesComeFirstAndMapsBecomeFlowYaml) {
  const SweepSpec s = parse(
      "scenarios: [../scenarios/a.yaml]\nset: {sim: {max_time: 5}}\n"
      "vary:\n  planner: [{name: astar, resolution: 1}]\n");
  const auto jobs = expandSweepJobs(s, root_ / "out");
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].overrides,
            (std::vector<std::string>{"sim.max_time=5", "planner={name: astar, resolution: 1}"}));
  EXPECT_NO_THROW(validateSweepJobs(s, jobs));
}

TEST_F(SweepSpecTest, ScenarioPathsResolveBesideTheSweepFileThenInTheCurrentDirectory) {
  const fs::path sweep = root_ / "sweeps/s.yaml";
  EXPECT_EQ(resolveSweepScenarioPath("../scenarios/a.yaml", sweep),
            (root_ / "scenarios/a.yaml").lexically_normal());
  const fs::path cwd = fs::current_path();
  fs::current_path(root_);
  EXPECT_EQ(resolveSweepScenarioPath("scenarios/b.yaml", sweep), fs::path("scenarios/b.yaml"));
  // Beside the sweep file wins when both exist.
  write(root_ / "sweeps/scenarios_b.yaml", kScenario);
  write(root_ / "scenarios_b.yaml", kScenario);
  EXPECT_EQ(resolveSweepScenarioPath("scenarios_b.yaml", sweep), root_ / "sweeps/scenarios_b.yaml");
  EXPECT_TRUE(resolveSweepScenarioPath("nowhere.yaml", sweep).empty());
  fs::current_path(cwd);
  EXPECT_EQ(resolveSweepScenarioPath((root_ / "scenarios/a.yaml").string(),
                                     fs::path("/elsewhere/s.yaml")),
            root_ / "scenarios/a.yaml");
}

TEST_F(SweepSpecTest, AMissingScenarioNamesItsLineAndKey) {
  EXPECT_EQ(errorOf("scenarios:\n  - ../scenarios/a.yaml\n  - ../scenarios/missing.yaml\n"),
            "line 3, key scenarios[1] | scenario file not found: '../scenarios/missing.yaml' "
            "(looked in " +
                (root_ / "sweeps").string() + " and in the current directory)");
}

TEST_F(SweepSpecTest, MalformedYamlAndUnknownSweepKeysAreLocated) {
  EXPECT_EQ(errorOf("scenarios: [../scenarios/a.yaml\nvary: {}\n").substr(0, 6), "line 2");
  EXPECT_EQ(
      errorOf("scenarios: [../scenarios/a.yaml]\nvary_: {sim.seed: [1]}\n"),
      "line 2, key vary_ | unknown key 'vary_' (did you mean 'vary'? allowed: name, scenarios, "
      "generators, vary, set, "
      "output, limits)");
  EXPECT_EQ(errorOf("scenarios: [../scenarios/a.yaml]\nvary:\n  sim.seed: []\n"),
            "line 3, key vary.sim.seed | needs at least one value");
  EXPECT_EQ(errorOf("scenarios: [../scenarios/a.yaml]\nlimits: {job_timeout_s: -1}\n"),
            "line 2, key limits.job_timeout_s | = -1 is outside [0.1, 1e+07]");
  EXPECT_EQ(errorOf("scenarios: [../scenarios/a.yaml]\nvary: {sim.seed: [1]}\noutput: {figure_by: "
                    "planner.name}\n"),
            "line 3, key output.figure_by | 'planner.name' is not a key under vary:");
  EXPECT_EQ(errorOf("vary: {sim.seed: [1]}\n"),
            "line 1, key scenarios | a sweep needs 'scenarios:' or 'generators:' (at least one)");
}

TEST_F(SweepSpecTest, AnUnknownScenarioKeyInVaryIsBadInputAtItsLine) {
  const std::string e = errorOf(
      "scenarios: [../scenarios/a.yaml]\nvary:\n  planner.name: [astar]\n  sim.sed: [1, 2]\n");
  EXPECT_EQ(e.substr(0, e.find(" | ")), "line 4, key vary.sim.sed");
  EXPECT_NE(e.find("unknown key 'sed'"), std::string::npos) << e;
}

// --set takes vehicles[0].goal; vary: refused it as "not a scenario key".
TEST_F(SweepSpecTest, VaryTakesTheIndexedKeysThatSetTakes) {
  const SweepSpec s = parse(
      "scenarios: [../scenarios/a.yaml]\nvary:\n  vehicles[0].goal: [[18, 18, 2], [18, 2, 2]]\n");
  const auto jobs = expandSweepJobs(s, root_ / "out");
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[1].overrides, (std::vector<std::string>{"vehicles[0].goal=[18, 2, 2]"}));
  EXPECT_NO_THROW(validateSweepJobs(s, jobs));
  EXPECT_EQ(errorOf("scenarios: [../scenarios/a.yaml]\nvary:\n  vehicles[00].goal: [[1, 1, 1]]\n"),
            "line 3, key vary.vehicles[00].goal | 'vehicles[00]': write the index without leading "
            "zeros (vehicles[0])");
  const std::string out_of_range =
      errorOf("scenarios: [../scenarios/a.yaml]\nvary:\n  vehicles[3].goal: [[1, 1, 1]]\n");
  EXPECT_EQ(out_of_range.substr(0, out_of_range.find(" | ")), "line 3, key vary.vehicles[3].goal")
      << out_of_range;
  EXPECT_NE(out_of_range.find("index 3 is out of range"), std::string::npos) << out_of_range;
}

TEST_F(SweepSpecTest, AnUnknownPlannerParameterIsBadInputAtItsLine) {
  const std::string e =
      errorOf("scenarios: [../scenarios/a.yaml]\nvary:\n  planner.stepp: [1, 2]\n");
  EXPECT_EQ(e.substr(0, e.find(" | ")), "line 3, key vary.planner.stepp");
  EXPECT_NE(e.find("unknown parameter 'stepp'"), std::string::npos) << e;
}

TEST_F(SweepSpecTest, VaryingThePlannerAcrossFamiliesKeepsTheOtherFamilysParameters) {
  // a.yaml sets planner.resolution, a grid parameter rrt_star does not take but another planner
  // does: the documented sweep example (astar, theta_star, rrt_star over one scenario) must be
  // valid.
  const SweepSpec s =
      parse("scenarios: [../scenarios/a.yaml]\nvary:\n  planner.name: [astar, rrt_star]\n");
  EXPECT_NO_THROW(validateSweepJobs(s, expandSweepJobs(s, root_ / "out")));
}

TEST_F(SweepSpecTest, AnUnknownPlannerNameIsBadInput) {
  const std::string e =
      errorOf("scenarios: [../scenarios/a.yaml]\nvary:\n  planner.name: [astar, a_star]\n");
  EXPECT_EQ(e.substr(0, e.find(" | ")), "line 3, key vary.planner.name");
  EXPECT_NE(e.find("planner.name=a_star"), std::string::npos) << e;
}

TEST_F(SweepSpecTest, GeneratorListsExpandToOneWorldEachWrittenIntoTheOutputFolder) {
  const SweepSpec s = parse(
      "generators:\n  - {type: forest, density: [0.02, 0.04], seed: [1, 2, 3], size: [20, 20, 6]}\n"
      "  - {type: maze, size: [15, 15, 3]}\n");
  const auto jobs = expandSweepJobs(s, root_ / "out");
  ASSERT_EQ(jobs.size(), 7u);
  EXPECT_EQ(jobs[0].scenario, "worlds/forest-d0.02-s1-20x20x6.yaml");
  EXPECT_EQ(jobs[5].scenario, "worlds/forest-d0.04-s3-20x20x6.yaml");
  EXPECT_EQ(jobs[6].scenario, "worlds/maze-d1-s1-15x15x3.yaml");
  EXPECT_TRUE(fs::exists(root_ / "out/worlds/maze-d1-s1-15x15x3.yaml"));
  EXPECT_NO_THROW(validateSweepJobs(s, jobs));
  EXPECT_EQ(errorOf("generators: [{type: forest, density: 0.7}]\n"),
            "line 1, key generators[0].density | = 0.7 is outside [0, 0.5]");
  EXPECT_EQ(errorOf("generators: [{type: desert}]\n"),
            "line 1, key generators[0].type | unknown generator 'desert' (forest, city, maze)");
}

TEST_F(SweepSpecTest, AChangedScenarioChangesTheJobFingerprint) {
  const SweepSpec s = parse("scenarios: [../scenarios/a.yaml]\nvary: {sim.seed: [1, 2]}\n");
  const auto before = expandSweepJobs(s, root_ / "out");
  EXPECT_NE(before[0].fingerprint, before[1].fingerprint);
  write(root_ / "scenarios/a.yaml", std::string(kScenario) + "# edited\n");
  const auto after = expandSweepJobs(s, root_ / "out");
  EXPECT_NE(before[0].fingerprint, after[0].fingerprint);
  EXPECT_EQ(after[0].fingerprint, expandSweepJobs(s, root_ / "out")[0].fingerprint);
}

// Every file a job's run reads is part of its fingerprint: a resumed sweep reruns the jobs whose
// world fragment, grid map, URDF or mesh changed, though their scenario text did not.
TEST_F(SweepSpecTest, AChangedIncludedFileChangesTheFingerprintOfTheJobsThatReadIt) {
  write(root_ / "scenarios/frag.xml", "<mujoco><worldbody/></mujoco>\n");
  write(root_ / "scenarios/map.map", "type octile\nheight 2\nwidth 2\nmap\n..\n..\n");
  write(root_ / "scenarios/mesh.stl", "solid m\nendsolid m\n");
  write(root_ / "scenarios/robot.urdf",
        "<robot name=\"r\"><link name=\"base\"><visual><geometry><mesh filename=\"mesh.stl\"/>"
        "</geometry></visual></link></robot>\n");
  write(root_ / "scenarios/inc.yaml",
        "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: frag.xml}\n"
        "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n");
  write(root_ / "scenarios/grid.yaml",
        "world: {grid_map: {file: map.map, cell: 1}}\n"
        "vehicles: [{name: r, model: robot.urdf, start: [0.5, 0.5, 0], goal: [1.5, 0.5, 0]}]\n");
  const SweepSpec s = parse("scenarios: [../scenarios/inc.yaml, ../scenarios/grid.yaml]\n");
  const auto fingerprints = [&] {
    std::vector<std::string> f;
    for (const auto& job : expandSweepJobs(s, root_ / "out")) f.push_back(job.fingerprint);
    return f;
  };
  const auto before = fingerprints();
  ASSERT_EQ(before.size(), 2u);
  EXPECT_EQ(fingerprints(), before);  // nothing changed, nothing reruns

  write(root_ / "scenarios/frag.xml",
        "<mujoco><worldbody><geom type=\"box\" size=\"1 1 1\" pos=\"10 10 "
        "1\"/></worldbody></mujoco>\n");
  auto after = fingerprints();
  EXPECT_NE(after[0], before[0]) << "the fragment changed";
  EXPECT_EQ(after[1], before[1]) << "the grid job does not read the fragment";

  const auto step = after;
  write(root_ / "scenarios/map.map", "type octile\nheight 2\nwidth 2\nmap\n.@\n..\n");
  after = fingerprints();
  EXPECT_EQ(after[0], step[0]);
  EXPECT_NE(after[1], step[1]) << "the grid map changed";

  const auto step2 = after;
  write(root_ / "scenarios/mesh.stl", "solid m2\nendsolid m2\n");
  after = fingerprints();
  EXPECT_NE(after[1], step2[1]) << "the URDF's mesh changed";

  const auto step3 = after;
  fs::remove(root_ / "scenarios/mesh.stl");
  after = fingerprints();
  EXPECT_NE(after[1], step3[1]) << "the URDF's mesh went missing";
}

// The bundled team scenario sweeps: its validation knows the team planners (cbs was "unknown").
TEST_F(SweepSpecTest, TeamAndNavigatorPlannersOfGroundScenariosValidate) {
  const std::string team =
      std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/ground_team.yaml";
  const SweepSpec s =
      parse("scenarios: [" + team + "]\nvary: {planner.name: [cbs, whca_star, astar]}\n");
  EXPECT_NO_THROW(validateSweepJobs(s, expandSweepJobs(s, root_ / "out")));
  EXPECT_EQ(errorOf("scenarios: [" + team + "]\nvary: {planner.window: [4]}\n"),
            "line 2, key vary.planner.window | scenario " + team +
                " with planner.window=4: " + team +
                ": --set planner.window=4, key planner.window: unknown parameter 'window' for "
                "planner 'cbs' (allowed: bypass, connectivity, max_expansions, max_nodes, "
                "resolution, time_limit)");
}

TEST(SweepShard, ShardsPartitionTheJobsRoundRobin) {
  const auto none = [](const char*) -> const char* { return nullptr; };
  const SweepShard a = parseSweepShard("1/3", none), b = parseSweepShard("2/3", none),
                   c = parseSweepShard("3/3", none);
  for (std::size_t id = 0; id < 30; ++id) EXPECT_EQ(a.owns(id) + b.owns(id) + c.owns(id), 1) << id;
  EXPECT_TRUE(b.owns(1));
  EXPECT_TRUE(b.owns(4));
  EXPECT_FALSE(b.owns(5));
  EXPECT_THROW(parseSweepShard("0/2", none), InputError);
  EXPECT_THROW(parseSweepShard("3/2", none), InputError);
  EXPECT_THROW(parseSweepShard("1-2", none), InputError);
  EXPECT_TRUE(parseSweepShard("auto", none).whole());
}

TEST(SweepShard, AutoReadsSlurmArrayVariables) {
  const auto slurm = [](const char* name) -> const char* {
    const std::string n = name;
    if (n == "SLURM_ARRAY_TASK_ID") return "5";
    if (n == "SLURM_ARRAY_TASK_MIN") return "4";
    if (n == "SLURM_ARRAY_TASK_COUNT") return "3";
    return nullptr;
  };
  const SweepShard s = parseSweepShard("auto", slurm);
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 3);
  const auto outside = [](const char* name) -> const char* {
    const std::string n = name;
    return n == "SLURM_ARRAY_TASK_ID"      ? "9"
           : n == "SLURM_ARRAY_TASK_MIN"   ? "1"
           : n == "SLURM_ARRAY_TASK_COUNT" ? "4"
                                           : nullptr;
  };
  EXPECT_THROW(parseSweepShard("auto", outside), InputError);
}

TEST(SweepJobDir, IdsArePaddedToTheWidthOfTheLargestId) {
  EXPECT_EQ(sweepJobDirName(7, 200), "0007");
  EXPECT_EQ(sweepJobDirName(12345, 20000), "12345");
  EXPECT_EQ(sweepJobDirName(42, 100000), "00042");
}

}  // namespace
}  // namespace cosim
