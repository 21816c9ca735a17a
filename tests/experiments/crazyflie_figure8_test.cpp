// `cosim reproduce crazyflie-figure8 --quick`: the study's files, and the prediction's shape: the
// faster the figure-eight, the larger the tracking error, and a firmware left at its default
// CF_MASS adds a height offset.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
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
  // How it follows the reference from its true start, per axis: a lag of a few hundredths of a
  // second at most and nearly the reference's size in x and y; the flat figure's z has neither.
  const nlohmann::json rows = nlohmann::json::parse(json)["rows"];
  ASSERT_FALSE(rows.empty());
  const nlohmann::json& lee = rows[0];
  ASSERT_EQ(lee["controller"], "crazyflie_lee");
  for (int a = 0; a < 2; ++a) {
    ASSERT_TRUE(lee["lag_s"][a].is_number()) << lee;
    EXPECT_LT(std::abs(lee["lag_s"][a].get<double>()), 0.1) << lee;
    EXPECT_NEAR(lee["amplitude_ratio"][a].get<double>(), 1.0, 0.1) << lee;
  }
  EXPECT_TRUE(lee["lag_s"][2].is_null()) << lee;
  EXPECT_TRUE(lee["amplitude_ratio"][2].is_null()) << lee;
  // A fitted start can only lower the RMSE.
  EXPECT_LE(lee["rmse_start_fitted_m"].get<double>(), lee["rmse_m"].get<double>() + 1e-12);
  EXPECT_GE(lee["fitted_start_s"].get<double>(), 0.0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim
