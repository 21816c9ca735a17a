// Reading one vehicle's flight from a run folder for compare-real: the vehicle of a team, the
// window of its reference, and whether the scenario flew that reference relative to its start.
#include "experiments/compare/run_flight.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "sim/run_log_io.h"
#include "tests/support/test_files.h"

namespace cosim::test {
namespace {

// Two vehicles at 10 Hz for 3 s; b's reference stands still for 0.5 s, moves along x until
// 2.0 s, then stands still again; a's never moves.
std::filesystem::path teamRunFolder() {
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
  const auto dir = freshDir("run-flight");
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir / "timeseries.csv", timeseriesCsv(log));
  writeFileAtomically(dir / "scenario.yaml",
                      "vehicles:\n  - {name: a, model: cf2, start: [0, 0, 1], goal: [1, 0, 1]}\n"
                      "  - name: b\n    model: cf2\n    start: [0, 1, 1]\n"
                      "    reference: {file: f.csv, relative: true}\n");
  return dir;
}

TEST(RunFlight, PicksTheNamedVehicleItsWindowAndItsRelativeReference) {
  const auto dir = teamRunFolder();
  const RunFlight b = readRunFlight(dir, "b");
  EXPECT_EQ(b.vehicle, "b");
  EXPECT_TRUE(b.relative_reference);
  ASSERT_EQ(b.reference.size(), 31u);
  // From the last still sample (0.5 s) to the first still one after the motion (2.0 s).
  EXPECT_NEAR(b.windowStart(), 0.5, 1e-9);
  EXPECT_NEAR(b.windowEnd(), 2.0, 1e-9);
  EXPECT_NEAR(b.flown.p[3].y(), 0.01, 1e-9);
  const RunFlight a = readRunFlight(dir, "a");
  EXPECT_FALSE(a.relative_reference);
  EXPECT_EQ(a.window_begin, 0u);  // a reference that never moves: the whole run
  EXPECT_EQ(a.window_end, 31u);
  try {
    readRunFlight(dir, "");
    ADD_FAILURE() << "a team run without --vehicle";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "command line: --vehicle: the run has several vehicles (a, b): name one");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
