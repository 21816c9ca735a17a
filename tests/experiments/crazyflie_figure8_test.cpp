// `cosim reproduce crazyflie-figure8 --quick`: the study's files, and the prediction's shape: the
// faster the figure-eight, the larger the tracking error, and a firmware left at its default
// CF_MASS adds a height offset.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "tests/support/cosim_command.h"

namespace cosim {
namespace {

// The rmse_m of the row with this controller and timescale in crazyflie-figure8.json.
double rmse(const std::string& json, const std::string& controller, const std::string& timescale) {
  const std::regex row("\\{[^{}]*\"controller\": \"" + controller +
                       "\"[^{}]*\"timescale\": " + timescale + "[^{}]*\"rmse_m\": ([0-9.eE+-]+)");
  std::smatch m;
  if (!std::regex_search(json, m, row)) return -1.0;
  return std::stod(m[1]);
}

TEST(CrazyflieFigure8, QuickStudyWritesItsFilesAndErrorGrowsWithSpeed) {
  const auto dir = test::freshDir("crazyflie-figure8");
  const auto r = test::runCosim("reproduce crazyflie-figure8 --quick --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = test::slurp(dir / "crazyflie-figure8.json");
  const std::string md = test::slurp(dir / "crazyflie-figure8.md");
  EXPECT_TRUE(std::filesystem::exists(dir / "crazyflie-figure8.png"));
  EXPECT_NE(md.find("Quick run"), std::string::npos);
  // With the firmware configured for the flown mass (the default), the error grows steeply with
  // speed (Lee's low position gains and its attitude lag on the heavier airframe).
  const double slow = rmse(json, "crazyflie_lee", "1"), fast = rmse(json, "crazyflie_lee", "0.5");
  ASSERT_GT(slow, 0.0) << json;
  ASSERT_GT(fast, 0.0) << json;
  EXPECT_GT(fast, 2.0 * slow);
  // Left at its default CF_MASS (39.3 g), the firmware flies the 37 g vehicle 8.2 cm high: the
  // offset dominates at low speed.
  const double unconfigured = rmse(json, "lee/firmware_default_mass", "1");
  EXPECT_GT(unconfigured, 0.06) << json;
  EXPECT_GT(unconfigured, 2.0 * slow);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim
