// End to end: bad inputs of every kind (malformed, truncated, wrong types, huge numbers, NaN,
// unreachable, overlapping, empty) make the built program exit 2 (bad input) or 1 (task failed)
// with one stderr line naming the problem, and never leave a result file that looks finished.
// docs/robustness.md's bad-input table lists these cases.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tests/cli/bad_input_case.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// Every case: scenario contents, then the command line and MovingAI files, then hardening.
std::vector<BadInput> badInputs() {
  std::vector<BadInput> cases = badScenarioInputs();
  for (auto&& more : {badCommandLineInputs(), hardeningBadInputs()})
    cases.insert(cases.end(), more.begin(), more.end());
  return cases;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, ExitsWithOneLineNamingTheProblemAndLeavesNoResult) {
  const BadInput& c = GetParam();
  const fs::path dir = freshDir("bad-input-" + c.name);
  fs::create_directories(dir);
  for (const auto& [name, content] : c.files) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << content;
  }
  if (!c.fifo.empty()) {
    ASSERT_EQ(::mkfifo((dir / c.fifo).c_str(), 0644), 0);
  }
  const bool is_map = c.args.rfind("grid-bench", 0) == 0 || c.args.rfind("mapf", 0) == 0;
  const fs::path in = dir / (is_map ? "x.map" : "scenario.yaml");
  const fs::path in2 = dir / "x.scen";
  std::ofstream(in, std::ios::binary) << c.content;
  std::ofstream(in2, std::ios::binary) << c.content2;
  // The output folder exists (as after an earlier run): what a command may leave there is checked
  // below, and a command writing a file into it (grid-bench) finds it.
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::string args = replaceAll(c.args, "{in}", in.string());
  args = replaceAll(args, "{in2}", in2.string());
  args = replaceAll(args, "{out}", out.string());
  args = replaceAll(args, "{dir}", dir.string());

  // Never a hang (the watchdog ends the program at 60 s: exit 124 or 137) and never more than
  // 1 GB of memory (the largest resident size of any program this test process has waited for;
  // ctest runs each case in a process of its own).
  const CommandResult r = runCosim(args, dir, 60);
  EXPECT_EQ(r.status, c.exit_code) << args << "\nstderr: " << r.err << "\nstdout: " << r.out;
  struct rusage usage {};
  ::getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 1024L * 1024L) << "KiB resident at most";  // ru_maxrss is in KiB
  // The program's own message, never a crash report or an internal error.
  const std::string all = r.err + r.out;
  const std::string message =
      replaceAll(replaceAll(c.message, "{in}", in.string()), "{dir}", dir.string());
  EXPECT_NE(all.find(message), std::string::npos) << "stderr: " << r.err << "\nstdout: " << r.out;
  // No raw control bytes from the input (a NUL would cut the line, an escape drive the terminal).
  EXPECT_EQ(std::count_if(r.err.begin(), r.err.end(),
                          [](unsigned char ch) { return (ch < 0x20 && ch != '\n') || ch == 0x7f; }),
            0)
      << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("Sanitizer"), std::string::npos) << r.err;
  if (c.exit_code == 2) {
    // Bad input: one line on stderr, and nothing written.
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const char* f : {"metrics.json", "plan.json", "bench.csv", "mapf.json", "path.csv"})
      EXPECT_FALSE(fs::exists(out / f)) << f;
    // A case writing to {dir}/new (a folder that does not exist yet) must not create it.
    EXPECT_FALSE(fs::exists(dir / "new")) << "bad input created its output folder";
  } else if (fs::exists(out / "metrics.json")) {
    // A failed task may write its result, but it must say it failed.
    const std::string metrics = slurp(out / "metrics.json");
    EXPECT_FALSE(jsonTrue(metrics, "reached_goal")) << metrics;
    EXPECT_EQ(jsonNumber(metrics, "status"), 1.0) << metrics;
    if (c.name == "absurd_gains_saturate") {
      EXPECT_NE(metrics.find("\"fault\": \"saturated\""), std::string::npos) << metrics;
      EXPECT_GT(jsonNumber(metrics, "longest_saturation_s"), 2.0) << metrics;
    }
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInputTest, ::testing::ValuesIn(badInputs()),
                         [](const ::testing::TestParamInfo<BadInput>& i) { return i.param.name; });

TEST(BadInputTable, CoversAtLeastThirtyDistinctBadInputs) {
  const auto cases = badInputs();
  EXPECT_GE(cases.size(), 30u);
  std::vector<std::string> names;
  for (const auto& c : cases) names.push_back(c.name);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

}  // namespace
}  // namespace cosim::test
