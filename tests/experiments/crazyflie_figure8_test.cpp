// `cosim reproduce crazyflie-figure8 --quick`: the study's files, and the prediction's shape: the
// faster the figure-eight, the larger the tracking error; the rig as flown lags its reference
// and flies inside it; a firmware left at its default CF_MASS adds a height offset.
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
  // speed (Lee's low position gains and its attitude lag, rotor drag the estimator ignores).
  const double slow = rmse(json, "crazyflie_lee", "1"), fast = rmse(json, "crazyflie_lee", "0.5");
  ASSERT_GT(slow, 0.0) << json;
  ASSERT_GT(fast, 0.0) << json;
  EXPECT_GT(fast, 1.5 * slow);
  const nlohmann::json rows = nlohmann::json::parse(json)["rows"];
  ASSERT_FALSE(rows.empty());
  const nlohmann::json& lee = rows[0];
  ASSERT_EQ(lee["controller"], "crazyflie_lee");
  // The battery starts at the charge where the firmware's PWM map holds the weight: no height
  // offset builds up, so removing the mean offset changes the RMSE by millimetres at most.
  EXPECT_LT(lee["rmse_m"].get<double>() - lee["rmse_offset_removed_m"].get<double>(), 0.005) << lee;
  // Left at its default CF_MASS (39.3 g), the firmware flies the 37 g vehicle 8.2 cm high: a
  // constant offset, most of its RMSE, that removing the mean offset takes away.
  const nlohmann::json* unconfigured = nullptr;
  for (const nlohmann::json& r : rows)
    if (r["controller"] == "lee/firmware_default_mass" && r["timescale"] == 1) unconfigured = &r;
  ASSERT_NE(unconfigured, nullptr) << json;
  EXPECT_GT((*unconfigured)["rmse_m"].get<double>(), 0.06) << *unconfigured;
  EXPECT_GT((*unconfigured)["rmse_m"].get<double>() -
                (*unconfigured)["rmse_offset_removed_m"].get<double>(),
            0.02)
      << *unconfigured;
  // How it follows the reference from its true start, per axis: late by a few hundredths of a
  // second and a little smaller than the reference (rotor drag against a velocity estimate that
  // ignores it); the flat figure's z has neither.
  EXPECT_GT(lee["lag_s"][0].get<double>(), 0.02) << lee;
  EXPECT_LT(lee["amplitude_ratio"][1].get<double>(), 0.95) << lee;
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
  EXPECT_LE(lee["rmse_start_fitted_offset_removed_m"].get<double>(),
            lee["rmse_start_fitted_m"].get<double>() + 1e-12);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim
