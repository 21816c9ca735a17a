// Seed 003's flight on its 3D map 3 (cosim reproduce seed003-flight): the thesis's pipeline, a
// point-mass Theta* plan on its own grid (cells blocked only when their centre is inside an
// obstacle) flown on raw waypoints with 0.2 m switching, puts the body into obstacles, as the
// thesis found; ours (a grown plan, minimum snap) keeps it clear. The first 20 s of each flight.
#include <gtest/gtest.h>

#include "run/run_pipeline.h"
#include "tests/support/test_files.h"

namespace cosim::test {
namespace {

FlightMetrics fly20s(const std::vector<std::string>& overrides, bool point_mass,
                     const std::string& name) {
  std::vector<std::string> all = overrides;
  all.push_back("sim.max_time=20");
  Scenario s =
      loadScenario(std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/zigzag_walls.yaml", all);
  RunRequest request;
  request.out_dir = freshDir(name);
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  request.plan_as_point_mass = point_mass;
  const RunRecord r = executeRun(s, request);
  std::filesystem::remove_all(request.out_dir);
  return r.metrics.vehicles.front();
}

TEST(Seed003Flight, ThesisPipelineIntrudesAndOursStaysClear) {
  const FlightMetrics thesis =
      fly20s({"planner={name: theta_star, resolution: 1.0, cell_blocking: centre}",
              "trajectory={mode: waypoints, switch_radius: 0.2}", "controller={name: cascade}"},
             true, "seed003-thesis");
  EXPECT_NEAR(thesis.planned_length_m, 78.19, 0.005);  // seed003-discrete's map 3 path
  EXPECT_TRUE(thesis.collisions > 0 || thesis.min_clearance_m < 0.0)
      << thesis.collisions << " " << thesis.min_clearance_m;
  const FlightMetrics ours =
      fly20s({"planner={name: theta_star, resolution: 0.5, margin: 0.3}",
              "trajectory={mode: minimum_snap, max_speed: 3.0, max_acceleration: 3.0}",
              "controller={name: geometric}"},
             false, "seed003-cosim");
  EXPECT_EQ(ours.collisions, 0);
  EXPECT_GT(ours.min_clearance_m, 0.3);
}

}  // namespace
}  // namespace cosim::test
