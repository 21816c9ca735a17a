// vehicles[i].reference in the scenario loader (sim/scenario_reference.h): the file found next
// to the scenario, placed by timescale and relative, its last point the goal; and each misuse
// refused at its key (or, for a defect inside the file, at the file's own line).
#include "sim/scenario_reference.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "control/piecewise_polynomial_reference.h"
#include "core/input_error.h"

namespace cosim {
namespace {

namespace fs = std::filesystem;

// A scenario in a fresh folder beside a copy of the bundled figure-eight and a bad file.
class ScenarioReference : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cosim-scenario-reference-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "refs");
    fs::copy_file(fs::path(COSIM_SOURCE_DIR) / "experiments/references/figure8.csv",
                  dir_ / "refs/figure8.csv", fs::copy_options::overwrite_existing);
    std::ofstream(dir_ / "refs/bad.csv") << "t,x,y,z\n0,0,0,1\n1,0,0,1\n0.5,0,0,1\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  Scenario parse(const std::string& vehicle, const std::vector<std::string>& sets = {}) {
    const std::string text =
        "world: {bounds: {min: [-3, -3, 0], max: [3, 3, 3]}}\n"
        "vehicles:\n  - " +
        vehicle + "\n";
    return parseScenario(text, (dir_ / "s.yaml").string(), sets);
  }
  // "file | place | problem" of the error parsing `vehicle` raises.
  std::string error(const std::string& vehicle, const std::vector<std::string>& sets = {}) {
    try {
      parse(vehicle, sets);
    } catch (const InputError& e) {
      return fs::path(e.file()).filename().string() + " | " + e.place() + " | " + e.problem();
    }
    ADD_FAILURE() << "accepted " << vehicle;
    return "";
  }
  fs::path dir_;
};

const std::string kFigure8 =
    "{name: cf, model: cf2, start: [0.5, 0.2, 1], reference: {file: refs/figure8.csv, "
    "timescale: 0.5, relative: true}}";

TEST_F(ScenarioReference, RelativeAddsTheStartAndTimescaleStretchesTheDuration) {
  const Scenario s = parse(kFigure8);
  const VehicleSpec& v = s.vehicles.front();
  ASSERT_TRUE(v.reference);
  EXPECT_EQ(v.reference_file, dir_ / "refs/figure8.csv");
  EXPECT_NEAR(v.reference->duration(), 0.5 * 7.283185, 1e-9);
  EXPECT_LT((v.reference->at(0.0).position - v.start).norm(), 1e-12);
  // The goal is its last point: the start again, to the file's 6 decimals.
  ASSERT_EQ(v.waypoints.size(), 1u);
  EXPECT_LT((v.goal() - v.start).norm(), 1e-5);
  // Twice as fast as the file: row 1's velocity at tau = 0.5 s, doubled, at t = 0.25 s.
  const double vx = 4 * 0.830443 / 8 - 5 * 0.276140 / 16 - 6 * 0.384219 / 32 + 7 * 0.180493 / 64;
  EXPECT_NEAR(v.reference->at(0.25).velocity.x(), 2.0 * vx, 1e-12);
}

TEST_F(ScenarioReference, SetChangesTheTimescale) {
  const Scenario s = parse(kFigure8, {"vehicles[0].reference.timescale=2"});
  EXPECT_NEAR(s.vehicles.front().reference->duration(), 2.0 * 7.283185, 1e-9);
}

TEST_F(ScenarioReference, MisusesAreRefusedAtTheirKey) {
  EXPECT_NE(error("{name: cf, model: cf2, start: [0, 0, 1], goal: [1, 1, 1], reference: {file: "
                  "refs/figure8.csv, relative: true}}")
                .find("s.yaml | line 3, key vehicles[0].goal | a vehicle with a 'reference' flies "
                      "it instead of a goal or waypoints"),
            std::string::npos);
  EXPECT_NE(error("{name: cf, model: cf2, start: [0, 0, 1], reference: {file: refs/figure8.csv}}")
                .find("key vehicles[0].reference | the reference starts at (0, 0, 0), 1 m from "
                      "the vehicle's start (0, 0, 1)"),
            std::string::npos);
  EXPECT_NE(error("{name: cf, model: cf2, start: [2.5, 0, 1], reference: {file: refs/figure8.csv, "
                  "relative: true}}")
                .find("key vehicles[0].reference | the reference leaves the world bounds at t = "),
            std::string::npos);
  EXPECT_NE(error("{name: cf, model: cf2, start: [0, 0, 1], reference: {file: refs/none.csv}}")
                .find("key vehicles[0].reference.file | "),
            std::string::npos);
  EXPECT_NE(error(kFigure8, {"vehicles[0].reference.timescale=0"})
                .find("vehicles[0].reference.timescale"),
            std::string::npos);
  EXPECT_NE(error("{name: cf, model: cf2, start: [0, 0, 1], reference: {file: refs/figure8.csv, "
                  "speed: 2}}")
                .find("unknown key 'speed'"),
            std::string::npos);
  EXPECT_NE(error("{name: r, model: omni_base, start: [0, 0, 0], reference: {file: "
                  "refs/figure8.csv}}")
                .find("ground robots follow planned paths"),
            std::string::npos);
}

TEST_F(ScenarioReference, ADefectInsideTheFileIsReportedAtTheFilesLine) {
  EXPECT_EQ(error("{name: cf, model: cf2, start: [0, 0, 1], reference: {file: refs/bad.csv}}"),
            "bad.csv | line 4, column t | time 0.5 is not after the previous row's 1 "
            "(times must increase, by at least 1e-6 s)");
}

}  // namespace
}  // namespace cosim
