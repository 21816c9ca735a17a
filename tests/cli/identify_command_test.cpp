// cosim identify end to end: a thrust stand's CSV gives FILE.yaml (readable as an airframe),
// FILE.md and a figure per fit; bad logs and foreign output files are bad input (exit 2, one
// line naming the file, the place and the problem), and nothing is written then.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/cosim_command.h"
#include "tests/support/test_files.h"

using namespace cosim::test;

namespace {

const std::string kStand =
    std::string(COSIM_TEST_DATA_DIR) + "/crazyflie/cf21bl_guards_thrust_stand.csv";

}  // namespace

TEST(IdentifyCommand, AThrustStandGivesKfInTheYamlTheReportAndFigures) {
  const auto dir = makeFreshDir("identify_command_ok");
  const CommandResult r =
      runCosim("identify '" + kStand + "' --out '" + (dir / "stand.yaml").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string yaml = slurp(dir / "stand.yaml");
  EXPECT_EQ(yaml.rfind("# cosim identify: airframe parameters", 0), 0u);
  EXPECT_NE(yaml.find("thrust_coefficient: {value: 3.91001e-08"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("# mass: not identified"), std::string::npos);
  EXPECT_NE(slurp(dir / "stand.md").find("| thrust constant k_f | 3.91001e-08"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "stand.thrust.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "stand.motor_map.svg"));
  // Its own output is replaced on a second run.
  EXPECT_EQ(
      runCosim("identify '" + kStand + "' --out '" + (dir / "stand.yaml").string() + "'").status,
      0);
}

TEST(IdentifyCommand, AnUnknownUnitAndAForeignOutputAreBadInputAndWriteNothing) {
  const auto dir = makeFreshDir("identify_command_bad");
  std::ofstream(dir / "bad.csv") << "pwm,vbat[V],rpm1,rpm2,rpm3,rpm4,thrust[lb]\n1,2,3,4,5,6,7\n"
                                 << "1,2,3,4,5,6,7\n1,2,3,4,5,6,7\n";
  CommandResult r = runCosim("identify '" + (dir / "bad.csv").string() + "' --out '" +
                             (dir / "out.yaml").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("bad.csv: line 1, column thrust[lb]: unknown unit 'lb' for thrust"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.yaml"));
  std::ofstream(dir / "mine.yaml") << "a: 1\n";
  r = runCosim("identify '" + kStand + "' --out '" + (dir / "mine.yaml").string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("was not written by cosim identify"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(dir / "mine.yaml"), "a: 1\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "mine.md"));
}
