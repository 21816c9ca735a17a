// A team's simulation loop with its second thread (the controllers and the step's forces run
// while MuJoCo computes positions and velocities) gives the same run, number for number, as on
// one thread: a mixed team whose quadrotor hits a robot (contacts), a quadrotor pair with noisy
// sensors, the EKF, downwash, rotor drag and gusts; with ground effect (forces that read MuJoCo's
// geometry) the loop stays on one thread.
#include <gtest/gtest.h>

#include <string>

#include "run/run_pipeline.h"
#include "sim/scenario.h"

namespace cosim {
namespace {

struct ThreadedRun {
  RunRecord summary;
  LoopProfile profile;
};

ThreadedRun runOn(int threads, const std::string& text, const std::vector<std::string>& overrides) {
  ThreadedRun r;
  RunRequest request;  // no folder: nothing written or rendered
  request.loop_threads = threads;
  request.profile = &r.profile;
  Scenario s = parseScenario(text, "threads_test.yaml", overrides);
  r.summary = executeRun(s, request);
  return r;
}

void expectSameLog(const RunLog& a, const RunLog& b) {
  EXPECT_EQ(a.end_reason, b.end_reason);
  EXPECT_EQ(a.physics_steps, b.physics_steps);
  ASSERT_EQ(a.vehicles.size(), b.vehicles.size());
  for (std::size_t v = 0; v < a.vehicles.size(); ++v) {
    const VehicleLog &x = a.vehicles[v], &y = b.vehicles[v];
    ASSERT_EQ(x.samples.size(), y.samples.size()) << x.name;
    for (std::size_t k = 0; k < x.samples.size(); ++k) {
      const LogSample &p = x.samples[k], &q = y.samples[k];
      // Exactly equal: the same operations on the same numbers in the same order.
      ASSERT_TRUE(p.t == q.t && p.pos == q.pos && p.vel == q.vel &&
                  p.att.coeffs() == q.att.coeffs() && p.omega == q.omega &&
                  p.est_pos == q.est_pos && p.est_vel == q.est_vel &&
                  p.est_att.coeffs() == q.est_att.coeffs() && p.ref_pos == q.ref_pos &&
                  p.rotor_cmd == q.rotor_cmd && p.rotor_thrust == q.rotor_thrust &&
                  p.rotor_speed == q.rotor_speed)
          << x.name << " sample " << k << " at t = " << p.t;
    }
    ASSERT_EQ(x.collisions.size(), y.collisions.size()) << x.name;
    for (std::size_t c = 0; c < x.collisions.size(); ++c) {
      EXPECT_EQ(x.collisions[c].t, y.collisions[c].t);
      EXPECT_EQ(x.collisions[c].other, y.collisions[c].other);
    }
  }
}

// A robot creeps across a cf2's straight path 5 cm above the floor: the cf2 hits it.
const std::string kCrossing =
    "world:\n  bounds: {min: [0, 0, 0], max: [4, 3, 2]}\nvehicles:\n"
    "  - {name: r0, model: omni_base, start: [2.0, 1.3, 0], goal: [2.0, 1.7, 0]}\n"
    "  - {name: uav1, model: cf2, start: [0.5, 1.5, 0.05], goal: [3.5, 1.5, 0.05]}\n"
    "aerial:\n  trajectory: {mode: minimum_snap, max_speed: 1.0}\n"
    "sim: {timestep: 0.002, control_rate: 250, max_time: 6}\n";

TEST(TeamLoopThreads, MixedTeamWithAContactRunsTheSameOnTwoThreadsAsOnOne) {
  const ThreadedRun one = runOn(1, kCrossing, {});
  const ThreadedRun two = runOn(2, kCrossing, {});
  EXPECT_FALSE(one.profile.overlapped);
  ASSERT_TRUE(two.profile.overlapped);  // the second thread did run
  std::size_t collisions = 0;
  for (const VehicleLog& v : one.summary.log.vehicles) collisions += v.collisions.size();
  EXPECT_GT(collisions, 0u);  // the contact path was exercised
  expectSameLog(one.summary.log, two.summary.log);
}

// Two quadrotors, one 1.5 m under the other, with motion-capture sensing and the EKF, downwash,
// rotor drag and gusts: every random stream and every air model on the second thread.
const std::string kStacked =
    "world:\n  bounds: {min: [0, -4, 0], max: [12, 4, 6]}\nvehicles:\n"
    "  - {name: upper, model: quad_1500g, start: [2, 0, 4], goal: [8, 0, 4]}\n"
    "  - {name: lower, model: quad_1500g, start: [2, 0, 2.5], goal: [8, 0, 2.5]}\n"
    "trajectory: {mode: minimum_snap, max_speed: 2.0, max_acceleration: 1.0}\n"
    "controller: {name: geometric}\nsensors: {preset: mocap}\n"
    "disturbances: {downwash: true, rotor_drag: true, wind: [1, 0, 0], gust: 0.5}\n"
    "sim: {timestep: 0.001, control_rate: 500, max_time: 3, seed: 7}\n";

TEST(TeamLoopThreads, QuadrotorsWithSensorsAndAirRunTheSameOnTwoThreadsAsOnOne) {
  const ThreadedRun one = runOn(1, kStacked, {});
  const ThreadedRun two = runOn(2, kStacked, {});
  ASSERT_TRUE(two.profile.overlapped);
  expectSameLog(one.summary.log, two.summary.log);
  EXPECT_EQ(one.summary.log.physics_steps, 3000);  // ran to max_time, not an early fault
}

TEST(TeamLoopThreads, GroundEffectKeepsTheLoopOnOneThread) {
  const ThreadedRun two = runOn(2, kStacked, {"disturbances.ground_effect=true"});
  EXPECT_FALSE(two.profile.overlapped);
  EXPECT_GT(two.profile.physics_steps, 0);
}

}  // namespace
}  // namespace cosim
