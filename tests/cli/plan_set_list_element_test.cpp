// Acceptance: `--set 'vehicles[0].goal=[...]'` plans to that goal, end to end.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

TEST(PlanSetListElement, AGoalSetByIndexIsWhereThePathEnds) {
  const fs::path out = freshDir("plan-set-goal");
  const std::string scenario =
      std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/default.yaml";
  const CommandResult r =
      runCosim("plan " + scenario + " --set 'vehicles[0].goal=[36,20,2.5]' --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = slurp(out / "path.csv");
  // The file's goal is [36, 26, 3]; the path now ends at the one given on the command line.
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  EXPECT_EQ(last, "36,20,2.5\n") << csv;
  fs::remove_all(out);
}

}  // namespace
}  // namespace cosim::test
