// Reading one vehicle's flight from a run folder for compare-real: the vehicle of a team, the
// window of its reference, and whether the scenario flew that reference relative to its start.
#include "experiments/compare/run_flight.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "tests/support/test_files.h"

namespace cosim::test {
namespace {

// Two vehicles at 10 Hz for 3 s; b's reference stands still for 0.5 s, moves along x until
// 2.0 s, then stands still again; a's never moves.
RunLog teamLog() {
  RunLog log;
  for (const char* name : {"a", "b"}) {
    VehicleLog v;
    v.name = name;
    for (int k = 0; k <= 30; ++k) {
      LogSample s;
      s.t = 0.1 * k;
      const double moved = std::clamp(s.t - 0.5, 0.0, 1.5);
      s.ref_pos = Eigen::Vector3d(v.name == "b" ? moved : 0.0, 0.0, 1.0);
      s.pos = s.ref_pos + Eigen::Vector3d(0.0, 0.01, 0.0);
      v.samples.push_back(s);
    }
    log.vehicles.push_back(v);
  }
  return log;
}

std::filesystem::path teamRunFolder() {
  const auto dir = freshDir("run-flight");
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir / "scenario.yaml",
                      "vehicles:\n  - {name: a, model: cf2, start: [0, 0, 1], goal: [1, 0, 1]}\n"
                      "  - name: b\n    model: cf2\n    start: [0, 1, 1]\n"
                      "    reference: {file: f.csv, relative: true}\n");
  return dir;
}

TEST(RunFlight, PicksTheNamedVehicleItsWindowAndItsRelativeReference) {
  const auto dir = teamRunFolder();
  const RunLog log = teamLog();
  const RunFlight b = runFlightOf(log, dir, "b");
  EXPECT_EQ(b.vehicle, "b");
  EXPECT_TRUE(b.relative_reference);
  ASSERT_EQ(b.reference.size(), 31u);
  // From the last still sample (0.5 s) to the first still one after the motion (2.0 s).
  EXPECT_NEAR(b.windowStart(), 0.5, 1e-9);
  EXPECT_NEAR(b.windowEnd(), 2.0, 1e-9);
  EXPECT_NEAR(b.flown.p[3].y(), 0.01, 1e-9);
  try {
    runFlightOf(log, dir, "");
    ADD_FAILURE() << "a team run without --vehicle";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "command line: --vehicle: the run has several vehicles (a, b): name one");
  }
  std::filesystem::remove_all(dir);
}

TEST(RunFlight, AReferenceThatNeverMovesIsRefused) {
  // a hovers: no window, and nothing by which to place a log in time.
  const auto dir = teamRunFolder();
  try {
    runFlightOf(teamLog(), dir, "a");
    ADD_FAILURE() << "a hover was compared";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "timeseries.csv").string() +
                  ": vehicle a: the reference never moves (a hover): there is no flight along it "
                  "to compare, and no motion by which to place a log in time");
  }
  std::filesystem::remove_all(dir);
}

TEST(RunFlight, APositionOf1e308MetresIsRefusedNamingItsTime) {
  const auto dir = teamRunFolder();
  RunLog log = teamLog();
  log.vehicles[1].samples[12].pos.z() = 1e308;
  try {
    runFlightOf(log, dir, "b");
    ADD_FAILURE() << "1e308 m was compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("timeseries.csv: vehicle b, t = 1.2 s: flown position "
                                         "[0.7, 0.01, 1e+308] m is not finite or beyond 1e+06 m"),
              std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
