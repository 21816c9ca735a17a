#pragma once
// A small known world and a synthetic flight log for the render tests: no planning, no physics.
#include <cmath>
#include <filesystem>
#include <string>

#include "sim/run_log.h"
#include "sim/scenario.h"
#include "tests/support/test_files.h"

namespace cosim::test {

// 20 x 20 x 6 m, one box, one quad_1500g from (3,3,2) to (17,5,2); small frames.
inline Scenario renderTestScenario(int width = 320, int height = 180) {
  Scenario s;
  s.file = "render_test.yaml";
  s.world.bounds_min = {0, 0, 0};
  s.world.bounds_max = {20, 20, 6};
  Obstacle box;
  box.type = ObstacleType::Box;
  box.pos = {10, 14, 2};
  box.size = {2, 2, 4};
  s.world.obstacles.push_back(box);
  VehicleSpec v;
  v.name = "uav1";
  v.model = "quad_1500g";
  v.model_file = modelsDirectory() / "quad_1500g.xml";
  v.start = {3, 3, 2};
  v.waypoints = {{17, 5, 2}};
  s.vehicles.push_back(v);
  s.motion.planner.name = "theta_star";
  s.motion.trajectory.mode = TrajectoryMode::MinimumSnap;
  s.render.width = width;
  s.render.height = height;
  s.render.fps = 10;
  return s;
}

// A straight flight from (3,3,2) to (17,5,2) over `seconds`, sampled at 100 Hz, with the
// vehicle lagging its reference by `lag` m along the way (so the tracking error is known).
inline RunLog straightFlightLog(double seconds, double lag = 0.2) {
  RunLog log;
  VehicleLog& v = log.vehicles.emplace_back();
  v.name = "uav1";
  v.radius = 0.35;
  v.goal = {17, 5, 2};
  v.planned_path = {{3, 3, 2}, {10, 6, 3}, {17, 5, 2}};
  const Eigen::Vector3d a(3, 3, 2), b(17, 5, 2);
  const Eigen::Vector3d dir = (b - a).normalized();
  const int n = static_cast<int>(std::lround(seconds * 100));
  for (int k = 0; k <= n; ++k) {
    LogSample s;
    s.t = k / 100.0;
    s.ref_pos = a + (b - a) * (static_cast<double>(k) / n);
    s.pos = s.ref_pos - lag * dir * std::sin(M_PI * k / n);
    s.vel = (b - a) / seconds;
    v.samples.push_back(s);
  }
  v.reached_goal = true;
  v.arrival_time = seconds;
  log.sim_time = seconds;
  log.end_reason = RunEnd::Goal;
  return log;
}

}  // namespace cosim::test
