// End to end: every CSV and JSON file cosim writes reads back with a real parser (nlohmann's for
// JSON, a strict RFC 4180 reader for CSV) for scenarios with unusual but legal names: a comma and
// quotes in vehicle names used to land unquoted in timeseries.csv, and `cosim render` of that very
// run then failed ("has 48 fields, header has 47").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;
using Table = std::vector<std::vector<std::string>>;

// RFC 4180, strictly: quoted fields may hold commas, quotes ("") and line breaks; a quote inside
// an unquoted field, text after a closing quote or an unclosed quote is an error; every record
// has as many fields as the header.
Table readCsvStrictly(const fs::path& file) {
  const std::string text = slurp(file);
  Table rows;
  std::vector<std::string> row;
  std::string field;
  std::size_t i = 0;
  const auto fail = [&](const std::string& why) {
    throw std::runtime_error(file.string() + ": byte " + std::to_string(i) + ": " + why);
  };
  while (i < text.size()) {
    field.clear();
    if (text[i] == '"') {
      for (++i;; ++i) {
        if (i >= text.size()) fail("unclosed quote");
        if (text[i] == '"' && i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else if (text[i] == '"') {
          ++i;
          break;
        } else {
          field += text[i];
        }
      }
      if (i < text.size() && text[i] != ',' && text[i] != '\n') fail("text after a closing quote");
    } else {
      for (; i < text.size() && text[i] != ',' && text[i] != '\n'; ++i) {
        if (text[i] == '"') fail("a quote inside an unquoted field");
        field += text[i];
      }
    }
    row.push_back(field);
    if (i >= text.size() || text[i] == '\n') {
      if (!rows.empty() && row.size() != rows.front().size())
        fail(std::to_string(row.size()) + " fields, the header has " +
             std::to_string(rows.front().size()));
      rows.push_back(row);
      row.clear();
    }
    ++i;  // the comma or the line break
  }
  return rows;
}

std::size_t column(const Table& t, const std::string& name) {
  for (std::size_t i = 0; i < t.at(0).size(); ++i)
    if (t[0][i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

nlohmann::json readJson(const fs::path& file) {
  return nlohmann::json::parse(slurp(file));
}

const std::string kCommaName = "a,b";
const std::string kQuoteName = "q\"x'y";

class OutputIntegrity : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshDir(std::string("output-integrity-") +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    std::ofstream(dir_ / "names.yaml")
        << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
           "vehicles:\n"
           "  - {name: 'a,b', model: cf2, start: [2, 2, 1], goal: [5, 2, 1]}\n"
           "  - {name: \"q\\\"x'y\", model: cf2, start: [2, 5, 1], goal: [5, 5, 1]}\n"
           "sim: {max_time: 10}\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(OutputIntegrity, ARunWithCommasAndQuotesInItsNamesReadsBackAndRendersAgain) {
  const fs::path run = dir_ / "run";
  const CommandResult r = runCosim("run " + (dir_ / "names.yaml").string() +
                                   " --no-video --no-images --quiet --out " + run.string());
  ASSERT_EQ(r.status, 0) << r.err;

  const nlohmann::json metrics = readJson(run / "metrics.json");
  EXPECT_TRUE(metrics.at("reached_goal").get<bool>());
  EXPECT_EQ(metrics.at("status").get<int>(), 0);
  ASSERT_EQ(metrics.at("vehicles").size(), 2u);
  EXPECT_EQ(metrics["vehicles"][0].at("name").get<std::string>(), kCommaName);
  EXPECT_EQ(metrics["vehicles"][1].at("name").get<std::string>(), kQuoteName);
  EXPECT_TRUE(readJson(run / "run.json").at("scenario_file").is_string());

  const Table series = readCsvStrictly(run / "timeseries.csv");
  ASSERT_GT(series.size(), 100u);
  const std::size_t vehicle = column(series, "vehicle");
  std::set<std::string> seen;
  for (std::size_t i = 1; i < series.size(); ++i) seen.insert(series[i][vehicle]);
  EXPECT_EQ(seen, (std::set<std::string>{kCommaName, kQuoteName}));
  EXPECT_EQ(std::stod(series.back()[column(series, "x")]) > 4.5, true);

  const Table path = readCsvStrictly(run / "path.csv");
  EXPECT_EQ(path[0], (std::vector<std::string>{"x", "y", "z", "vehicle"}));
  EXPECT_EQ(path[1][3], kCommaName);
  EXPECT_EQ(path.back()[3], kQuoteName);

  // The run's own log renders again (it used to be refused as malformed).
  const CommandResult again =
      runCosim("render " + run.string() + " --out " + (dir_ / "frame.png").string() + " --quiet");
  EXPECT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(fs::exists(dir_ / "frame.png"));
}

TEST_F(OutputIntegrity, PlanSweepGridBenchAndMapfFilesReadBack) {
  // cosim plan: plan.json and path.csv.
  const CommandResult plan = runCosim("plan " + (dir_ / "names.yaml").string() +
                                      " --planner astar --out " + (dir_ / "plan").string());
  ASSERT_EQ(plan.status, 0) << plan.err;
  const nlohmann::json p = readJson(dir_ / "plan" / "plan.json");
  EXPECT_TRUE(p.at("success").get<bool>());
  EXPECT_GT(p.at("length_m").get<double>(), 2.9);
  EXPECT_EQ(readCsvStrictly(dir_ / "plan" / "path.csv")[0],
            (std::vector<std::string>{"x", "y", "z"}));

  // cosim sweep: results.csv, summary.csv and each job's result.json.
  std::ofstream(dir_ / "sweep.yaml") << "scenarios: [names.yaml]\nvary: {sim.seed: [1, 2]}\n"
                                        "output: {video: false}\n";
  const CommandResult sweep = runCosim("sweep " + (dir_ / "sweep.yaml").string() +
                                       " --quiet --out " + (dir_ / "sweep").string());
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const Table results = readCsvStrictly(dir_ / "sweep" / "results.csv");
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[1][column(results, "status")], "ok");
  EXPECT_EQ(results[1][column(results, "vehicles[0].name")], kCommaName);
  EXPECT_EQ(results[1][column(results, "vehicles[1].name")], kQuoteName);
  EXPECT_GT(readCsvStrictly(dir_ / "sweep" / "summary.csv").size(), 1u);
  for (const auto& job : {"0000", "0001"}) {
    const nlohmann::json result = readJson(dir_ / "sweep" / "jobs" / job / "result.json");
    EXPECT_EQ(result.at("status").get<std::string>(), "ok");
  }

  // cosim grid-bench and cosim mapf.
  const std::string data = COSIM_TEST_DATA_DIR "/movingai/";
  const CommandResult bench =
      runCosim("grid-bench " + data + "arena.map " + data + "arena.map.scen --planner astar " +
               "--limit 5 --out " + (dir_ / "bench.csv").string());
  ASSERT_EQ(bench.status, 0) << bench.err;
  const Table b = readCsvStrictly(dir_ / "bench.csv");
  EXPECT_EQ(b.size(), 6u);
  EXPECT_EQ(b[0][0], "id");
  const std::string maps = COSIM_SOURCE_DIR "/experiments/maps/";
  const CommandResult mapf = runCosim("mapf " + maps + "empty-8-8.map " + maps +
                                      "empty-8-8-random-1.scen --agents 4 --planner cbs --out " +
                                      (dir_ / "mapf").string());
  ASSERT_EQ(mapf.status, 0) << mapf.err;
  const nlohmann::json m = readJson(dir_ / "mapf" / "mapf.json");
  EXPECT_TRUE(m.at("success").get<bool>());
  EXPECT_EQ(m.at("agents").get<int>(), 4);
  EXPECT_EQ(m.at("conflicts").get<int>(), 0);
  const Table paths = readCsvStrictly(dir_ / "mapf" / "paths.csv");
  EXPECT_EQ(paths[0], (std::vector<std::string>{"agent", "t", "x", "y"}));
}

TEST_F(OutputIntegrity, AGroundRunWithMovingObstaclesWritesFilesThatReadBack) {
  std::ofstream(dir_ / "ground.yaml")
      << "world:\n  bounds: {min: [0, 0, 0], max: [12, 8, 2]}\n  moving_obstacles:\n"
         "    - {type: cylinder, radius: 0.3, height: 1, speed: 0.5, path: [[9, 6], [9, 2]]}\n"
         "vehicles: [{name: 'r,1', model: omni_base, start: [1, 1, 0], goal: [4, 1, 0]}]\n"
         "sim: {timestep: 0.002, control_rate: 50, max_time: 15}\n";
  const fs::path run = dir_ / "ground";
  const CommandResult r = runCosim("run " + (dir_ / "ground.yaml").string() +
                                   " --no-video --no-images --quiet --out " + run.string());
  ASSERT_LE(r.status, 1) << r.err;
  const nlohmann::json metrics = readJson(run / "metrics.json");
  EXPECT_EQ(metrics.at("vehicles")[0].at("name").get<std::string>(), "r,1");
  const Table obstacles = readCsvStrictly(run / "moving_obstacles.csv");
  EXPECT_EQ(obstacles[0], (std::vector<std::string>{"t", "name", "x", "y", "z"}));
  EXPECT_GT(obstacles.size(), 10u);
  const Table series = readCsvStrictly(run / "timeseries.csv");
  EXPECT_EQ(series[1][column(series, "vehicle")], "r,1");
}

}  // namespace
}  // namespace cosim::test
