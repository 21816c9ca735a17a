// End to end: the bundled crazyflie_figure8.yaml flies Crazyswarm's figure-eight as given (not
// planned). Its rmse_m covers exactly the reference's duration (recomputed here from
// timeseries.csv over [0, duration], as an outside script would), the logged ref_x..ref_z are
// the reference at each logged time, and a sim.max_time shorter than the reference says so.
#include "experiments/bench/reference_flight.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "control/piecewise_polynomial_reference.h"
#include "run/run_pipeline.h"
#include "tests/support/test_files.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

struct Flown {
  RunRecord summary;
  nlohmann::json metrics;
  std::vector<std::vector<double>> rows;  // timeseries.csv's t, ref_x, ref_y, ref_z, x, y, z
  Scenario scenario;
};

Flown flyFigureEight(const std::string& name, const std::vector<std::string>& sets) {
  Flown f;
  f.scenario = loadScenario(
      std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/crazyflie_figure8.yaml", sets);
  RunRequest request;
  request.out_dir = freshDir(name);
  fs::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  Scenario s = f.scenario;
  f.summary = executeRun(s, request);
  f.metrics = nlohmann::json::parse(slurp(request.out_dir / "metrics.json"));
  std::ifstream in(request.out_dir / "timeseries.csv");
  std::string line, field;
  std::getline(in, line);
  std::vector<std::string> header;
  for (std::stringstream names(line); std::getline(names, field, ',');) header.push_back(field);
  std::vector<std::size_t> wanted;  // the columns of t, ref_x, ref_y, ref_z, x, y, z
  for (const char* name : {"t", "ref_x", "ref_y", "ref_z", "x", "y", "z"})
    wanted.push_back(
        static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin()));
  EXPECT_LT(*std::max_element(wanted.begin(), wanted.end()), header.size()) << line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    for (std::stringstream values(line); std::getline(values, field, ',');) fields.push_back(field);
    std::vector<double> row;
    for (std::size_t c : wanted) row.push_back(std::stod(fields.at(c)));
    f.rows.push_back(row);
  }
  fs::remove_all(request.out_dir);
  return f;
}

// RMS of |p - ref| over the rows with t <= until.
double rmseUntil(const std::vector<std::vector<double>>& rows, double until, std::size_t& n) {
  double sum = 0.0;
  n = 0;
  for (const auto& r : rows) {
    if (r[0] > until + 1e-9) continue;
    sum += std::pow(r[4] - r[1], 2) + std::pow(r[5] - r[2], 2) + std::pow(r[6] - r[3], 2);
    ++n;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

TEST(ReferenceFlight, FigureEightRmseCoversTheReferencesDurationAndRefColumnsAreTheReference) {
  const Flown f = flyFigureEight("figure8-reference", {});
  ASSERT_EQ(f.summary.exitStatus(), 0) << f.summary.message;
  EXPECT_TRUE(f.metrics["reached_goal"].get<bool>());
  EXPECT_EQ(f.metrics["planning_time_ms"].get<double>(), 0.0);  // not planned
  const auto& v = f.metrics["vehicles"][0];
  const double duration = v["reference_duration_s"].get<double>();
  EXPECT_NEAR(duration, 7.283185, 1e-9);
  EXPECT_EQ(v["error_reference"], "trajectory");
  // The run goes on after the reference (settling), but the RMSE stops at its end.
  ASSERT_GT(f.rows.back()[0], duration + 0.9);
  std::size_t n = 0;
  const double rmse = rmseUntil(f.rows, duration, n);
  EXPECT_EQ(n, static_cast<std::size_t>(std::floor(duration * 500)) + 1);  // 500 Hz from t = 0
  EXPECT_NEAR(f.metrics["rmse_m"].get<double>(), rmse, 1e-6 * rmse);
  std::size_t all = 0;
  EXPECT_GT(std::abs(rmseUntil(f.rows, 1e9, all) - rmse), 1e-6);  // the window matters
  // Centimetres at 1.2 m/s peak with the firmware's Lee controller on motion capture and the EKF.
  EXPECT_GT(rmse, 0.002);
  EXPECT_LT(rmse, 0.10);
  // The logged reference is the reference at each logged time.
  const auto& ref = *f.scenario.vehicles.front().reference;
  for (std::size_t i = 0; i < f.rows.size(); i += 397) {
    const Eigen::Vector3d p = ref.at(f.rows[i][0]).position;
    EXPECT_NEAR(f.rows[i][1], p.x(), 1e-8) << "t = " << f.rows[i][0];
    EXPECT_NEAR(f.rows[i][2], p.y(), 1e-8);
    EXPECT_NEAR(f.rows[i][3], p.z(), 1e-8);
  }
}

TEST(ReferenceFlight, AReferenceLongerThanMaxTimeSaysSoAndTheRmseCoversTheRun) {
  // At timescale 2 the figure-eight lasts 14.6 s; the run stops at 3 s.
  const Flown f =
      flyFigureEight("figure8-max-time", {"vehicles[0].reference.timescale=2", "sim.max_time=3"});
  EXPECT_EQ(f.summary.exitStatus(), 1);
  EXPECT_EQ(f.summary.message, "the reference lasts 14.57 s, longer than sim.max_time 3 s");
  EXPECT_EQ(f.metrics["message"], f.summary.message);
  EXPECT_FALSE(f.metrics["reached_goal"].get<bool>());
  std::size_t n = 0;
  EXPECT_NEAR(f.metrics["rmse_m"].get<double>(), rmseUntil(f.rows, 1e9, n), 1e-6);
}

TEST(ReferenceFlight, BenchSectionComparesTheLoopWithBareStepsOnTheSameFlight) {
  const bench::Section s = bench::measureReferenceFlight(true, "crazyflie_mellinger");
  EXPECT_EQ(s.name, "reference_flight");
  std::map<std::string, double> figures;
  for (const auto& f : s.figures) figures[f.name] = f.value;
  ASSERT_EQ(figures.count("ratio_to_bare"), 1u);
  EXPECT_GT(figures["ratio_to_bare"], 0.0);
  EXPECT_NEAR(figures["ratio_to_bare"],
              figures["full_loop_steps_per_s"] / figures["bare_mj_step_steps_per_s"], 1e-9);
  EXPECT_GT(figures["rmse_m"], 1e-4);  // it flew the reference (2 s of it)
  EXPECT_LT(figures["rmse_m"], 0.2);
  EXPECT_NE(s.note.find("under crazyflie_mellinger"), std::string::npos) << s.note;
  // The same flight with the EKF instead of the firmware's Kalman estimator (the scenario's).
  ASSERT_EQ(figures.count("ekf_ratio_to_bare"), 1u);
  EXPECT_GT(figures["ekf_ratio_to_bare"], 0.0);
  EXPECT_GT(figures["ekf_rmse_m"], 1e-4);
  EXPECT_LT(figures["ekf_rmse_m"], 0.2);
  EXPECT_NE(figures["ekf_rmse_m"], figures["rmse_m"]);  // another estimator flew it
}

}  // namespace
}  // namespace cosim::test
