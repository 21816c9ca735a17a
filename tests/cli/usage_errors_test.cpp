// End to end: numbers and keys on the command line that a lenient parser would take for other
// ones are refused with exit 2, naming the option. CLI11 reads "-1" into an unsigned seed as
// 2^64 - 1 and wrote that seed; "vehicles[00]" was taken as vehicles[0], after which an error
// about the value was placed at "line 1" of the file instead of at the --set.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

TEST(UsageErrors, ASeedThatIsNotAWholeNumberFrom0To2To64Minus1ExitsTwo) {
  for (const std::string seed : {"-1", "1e23", "18446744073709551616", "+5", "0x10"}) {
    for (const std::string command :
         {"reproduce seed003-flight --quick", "mapf a.map a.scen --agents 2"}) {
      const CommandResult r = runCosim(command + " --seed '" + seed + "'");
      EXPECT_EQ(r.status, 2) << command << " --seed '" << seed << "': " << r.err;
      EXPECT_NE(r.err.find("--seed"), std::string::npos) << r.err;
      EXPECT_NE(
          r.err.find("must be a whole number from 0 to 18446744073709551615, got '" + seed + "'"),
          std::string::npos)
          << r.err;
    }
  }
}

TEST(UsageErrors, AListIndexWithLeadingZerosInASetIsRefusedAtTheSet) {
  const fs::path dir = freshDir("usage-set-index");
  fs::create_directories(dir);
  std::ofstream(dir / "s.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [8, 2, 1]}]\n";
  const CommandResult r =
      runCosim("plan " + (dir / "s.yaml").string() + " --set 'vehicles[00].goal=[1, 2]'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err,
            "cosim: command line: --set vehicles[00].goal=[1, 2]: 'vehicles[00]': write the index "
            "without leading zeros (vehicles[0])\n");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
