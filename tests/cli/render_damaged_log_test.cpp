// End to end: `cosim render` re-renders a run from its logs, and a log a run did not write that
// way is refused with exit 2 naming the file and the row: a NaN (the flown path vanished from
// the picture), a header alone, a repeated row, a file cut at a line boundary (it parses: only
// the row count the run recorded in run.json tells). The run's own logs always render.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines(const fs::path& p) {
  std::istringstream in(slurp(p));
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

void writeLines(const fs::path& p, const std::vector<std::string>& rows) {
  std::ofstream out(p, std::ios::trunc);
  for (const auto& r : rows) out << r << "\n";
}

class RenderDamagedLog : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = freshDir("render-damaged");
    fs::create_directories(root_);
    std::ofstream(root_ / "s.yaml")
        << "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}}\n"
           "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [8, 2, 1]}]\n"
           "planner: {name: astar, resolution: 0.5}\nsim: {max_time: 30}\n";
    const CommandResult r =
        runCosim("run " + (root_ / "s.yaml").string() + " --no-video --no-images --quiet --out " +
                 (root_ / "run").string());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }

  // A copy of the run whose timeseries.csv `damage` changed; render's result on it.
  CommandResult renderDamaged(const std::function<void(std::vector<std::string>&)>& damage) {
    const fs::path copy = root_ / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(copy);
    fs::copy(root_ / "run", copy, fs::copy_options::recursive);
    std::vector<std::string> rows = lines(copy / "timeseries.csv");
    damage(rows);
    writeLines(copy / "timeseries.csv", rows);
    return runCosim("render " + copy.string() + " --at 1 --out " + (copy / "at1.png").string());
  }
  std::string file() const {
    return (root_ / ::testing::UnitTest::GetInstance()->current_test_info()->name() /
            "timeseries.csv")
        .string();
  }
  static fs::path root_;
};

fs::path RenderDamagedLog::root_;

TEST_F(RenderDamagedLog, TheRunsOwnLogRenders) {
  const CommandResult r = renderDamaged([](std::vector<std::string>&) {});
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(RenderDamagedLog, ANanRowExitsTwoNamingRowAndColumn) {
  const CommandResult r = renderDamaged([](std::vector<std::string>& rows) {
    // Row 5's x (the 8th column: t, ref_x, ref_y, ref_z, ref_vx, ref_vy, ref_vz, x).
    std::string& row = rows.at(4);
    std::size_t at = 0;
    for (int comma = 0; comma < 7; ++comma) at = row.find(',', at) + 1;
    row.replace(at, row.find(',', at) - at, "nan");
  });
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, "cosim: " + file() +
                       ": line 5, column x: not a finite number: 'nan' (only a run that diverged "
                       "logs one)\n");
}

TEST_F(RenderDamagedLog, AHeaderAloneExitsTwo) {
  const CommandResult r = renderDamaged([](std::vector<std::string>& rows) { rows.resize(1); });
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err,
            "cosim: " + file() + ": line 2: no rows after the header: the log holds no flight\n");
}

TEST_F(RenderDamagedLog, ARepeatedRowExitsTwoNamingIt) {
  const CommandResult r = renderDamaged(
      [](std::vector<std::string>& rows) { rows.insert(rows.begin() + 3, rows.at(2)); });
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(file() + ": line 4, column t: time "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("again for vehicle 'uav1': a repeated row"), std::string::npos) << r.err;
}

TEST_F(RenderDamagedLog, ALogCutAtALineBoundaryExitsTwoNamingWhereItEnds) {
  std::size_t kept = 0;
  const CommandResult r = renderDamaged([&](std::vector<std::string>& rows) {
    rows.resize(rows.size() - 3);
    kept = rows.size() - 1;  // data rows
  });
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err, "cosim: " + file() + ": line " + std::to_string(kept + 2) +
                       ": the log ends after " + std::to_string(kept) +
                       " rows, but the run wrote " + std::to_string(kept + 3) +
                       " (run.json): the file was cut short\n");
}

}  // namespace
}  // namespace cosim::test
