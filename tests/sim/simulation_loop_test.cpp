// The simulation loop stepped from outside, one control period at a time: time advances by whole
// control periods, stepping it by hand is the same run as simulateFlight, a controller swapped
// between steps takes over at the next one, and the true state it reports is MuJoCo's.
#include "sim/simulation_loop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "control/geometric_controller.h"
#include "control/ground_velocity_tracker.h"
#include "control/waypoint_reference.h"
#include "sim/flight_simulation.h"
#include "sim/world_model.h"
#include "tests/sim/single_vehicle_scenario.h"

namespace cosim {
namespace {

// Commands no thrust at all: the vehicle falls.
class ZeroThrustController : public FlightController {
 public:
  std::string name() const override { return "zero_thrust"; }
  void reset() override {}
  ControlOutput update(const VehicleState&, const FlatReference&, double) override {
    return ControlOutput{};
  }
};

// One quadrotor flying to (or holding) the scenario's goal under the geometric controller.
struct OneQuadrotor {
  explicit OneQuadrotor(const Scenario& s)
      : world(WorldModel::build(s)),
        controller(world.vehicles()[0].params, GeometricGains{}),
        reference({s.vehicles[0].goal()}, 0.0),
        pilots(1) {
    pilots[0].controller = &controller;
    pilots[0].reference = &reference;
    pilots[0].goal = s.vehicles[0].goal();
  }
  WorldModel world;
  GeometricController controller;
  WaypointReference reference;
  std::vector<VehiclePilot> pilots;
  std::vector<GroundPilot> no_robots;
};

FlightOptions flightOptions(const Scenario& s) {
  FlightOptions o;
  o.settings = s.sim;
  return o;
}

TEST(SimulationLoop, SteppingNControlPeriodsAdvancesTimeByNOverTheControlRate) {
  const Scenario s = test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 5.0);
  OneQuadrotor q(s);
  SimulationLoop loop(q.world, s, q.no_robots, q.pilots, flightSimulationOptions(flightOptions(s)));
  EXPECT_DOUBLE_EQ(loop.controlRate(), 500.0);
  EXPECT_EQ(loop.time(), 0.0);
  for (int n = 1; n <= 137; ++n) {
    ASSERT_TRUE(loop.stepControl());
    // Two physics steps of 1 ms per period: a step too many or too few would be 1e-3 off.
    ASSERT_NEAR(loop.time(), n / 500.0, 1e-12) << "after " << n << " control periods";
  }
  EXPECT_FALSE(loop.done());
  EXPECT_EQ(loop.endReason(), RunEnd::Running);
}

TEST(SimulationLoop, SteppedByHandToTheEndGivesTheLogOfSimulateFlight) {
  // A 1 m hop: arrives and holds 1 s ("goal") well within max_time.
  const Scenario s = test::singleVehicleScenario({0, 0, 2}, {1, 0, 2.5}, 6.0);
  OneQuadrotor run(s);
  const RunLog expected = simulateFlight(run.world, s, run.pilots, flightOptions(s));

  OneQuadrotor stepped(s);
  SimulationLoop loop(stepped.world, s, stepped.no_robots, stepped.pilots,
                      flightSimulationOptions(flightOptions(s)));
  long periods = 0;
  while (loop.stepControl()) ++periods;
  EXPECT_TRUE(loop.done());
  const RunLog log = loop.finish();

  ASSERT_EQ(expected.end_reason, RunEnd::Goal);
  EXPECT_EQ(log.end_reason, expected.end_reason);
  EXPECT_EQ(log.physics_steps, expected.physics_steps);
  ASSERT_EQ(log.vehicles[0].samples.size(), expected.vehicles[0].samples.size());
  // A flight logs every control step, the last one the step that found the goal held.
  EXPECT_EQ(static_cast<long>(log.vehicles[0].samples.size()), periods + 1);
  const LogSample& a = log.vehicles[0].samples.back();
  const LogSample& b = expected.vehicles[0].samples.back();
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.pos.x(), b.pos.x());
  EXPECT_EQ(a.pos.y(), b.pos.y());
  EXPECT_EQ(a.pos.z(), b.pos.z());
  EXPECT_EQ(log.vehicles[0].arrival_time, expected.vehicles[0].arrival_time);
}

TEST(SimulationLoop, ControllerSwappedForZeroThrustMidRunFallsAlmostFreely) {
  const Scenario s = test::singleVehicleScenario({0, 0, 8}, {0, 0, 8}, 5.0);
  OneQuadrotor q(s);
  FlightOptions o = flightOptions(s);
  o.hold_after_arrival = 1e9;  // only max_time ends the run
  SimulationLoop loop(q.world, s, q.no_robots, q.pilots, flightSimulationOptions(o));
  while (loop.time() < 1.0 - 1e-9) ASSERT_TRUE(loop.stepControl());
  const double z0 = loop.vehicleState(0).position.z();
  ASSERT_NEAR(z0, 8.0, 0.05);  // hovering at the goal

  ZeroThrustController off;
  q.pilots[0].controller = &off;
  const double t0 = loop.time(), fall = 1.0;
  while (loop.time() < t0 + fall - 1e-9) ASSERT_TRUE(loop.stepControl());
  const double drop = z0 - loop.vehicleState(0).position.z();
  // Free fall would drop 0.5 g t^2 = 4.9 m in 1 s; the rotors spin down with a lag (25 ms time
  // constant), so a little less, but far more than a controller still flying would allow.
  const double g = q.world.vehicles()[0].params.gravity;
  EXPECT_GT(drop, 0.8 * 0.5 * g * fall * fall);
  EXPECT_LT(drop, 0.5 * g * fall * fall + 1e-6);
}

TEST(SimulationLoop, VehicleStateOfAQuadrotorIsItsFreeJointsQposAndQvel) {
  const Scenario s = test::singleVehicleScenario({0, 0, 2}, {2, 1, 3}, 5.0);
  OneQuadrotor q(s);
  SimulationLoop loop(q.world, s, q.no_robots, q.pilots, flightSimulationOptions(flightOptions(s)));
  for (int n = 0; n < 300; ++n) ASSERT_TRUE(loop.stepControl());  // flying: nothing is zero
  const TrueVehicleState x = loop.vehicleState(0);
  const VehicleHandles& h = q.world.vehicles()[0];
  const mjtNum* qpos = loop.data()->qpos + h.qpos_adr;
  const mjtNum* qvel = loop.data()->qvel + h.qvel_adr;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(x.position[i], qpos[i]);
    EXPECT_EQ(x.velocity[i], qvel[i]);
    EXPECT_EQ(x.angular_velocity[i], qvel[3 + i]);
  }
  for (int i = 0; i < 4; ++i) EXPECT_EQ(x.quaternion[i], qpos[3 + i]);  // w, x, y, z
  EXPECT_GT(x.velocity.norm(), 0.1);
}

TEST(SimulationLoop, VehicleStateOfAPlanarBaseIsTheBodysPoseInMujoco) {
  const Scenario s = parseScenario(
      "world:\n  bounds: {min: [0, 0, 0], max: [6, 6, 2]}\nvehicles:\n"
      "  - {name: r, model: omni_base, start: [3, 2, 0], goal: [3, 2, 0], yaw: 30}\n"
      "sim: {timestep: 0.002, control_rate: 50, max_time: 2}\n",
      "test.yaml");
  const WorldModel world = WorldModel::build(s);
  const VehicleHandles& h = world.vehicles()[0];
  ASSERT_TRUE(h.drive.planar_root);
  GroundVelocityTracker controller{GroundMotionLimits{}};
  GroundTimedPath path;
  path.append(0.0, {3, 2});
  std::vector<GroundPilot> robots(1);
  robots[0].controller = &controller;
  robots[0].path = &path;
  robots[0].yaw = 30.0 * M_PI / 180.0;
  robots[0].goal = {3, 2, 0};
  std::vector<VehiclePilot> no_quadrotors;
  SimulationOptions o;
  o.settings = s.sim;
  SimulationLoop loop(world, s, robots, no_quadrotors, o);
  // At the start (the loop has run mj_forward): MuJoCo's own kinematics of the base body.
  const TrueVehicleState x = loop.vehicleState(0);
  const mjData* d = loop.data();
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(x.position[i], d->xpos[3 * h.body + i], 1e-12);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.quaternion[i], d->xquat[4 * h.body + i], 1e-12);
  EXPECT_NEAR(x.quaternion[0], std::cos(M_PI / 12), 1e-12);  // 30 degrees about z
}

TEST(SimulationLoop, FinishBeforeTheEndIsAnInterruptedRunOfTheStepsTaken) {
  const Scenario s = test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 5.0);
  OneQuadrotor q(s);
  SimulationLoop loop(q.world, s, q.no_robots, q.pilots, flightSimulationOptions(flightOptions(s)));
  for (int n = 0; n < 25; ++n) ASSERT_TRUE(loop.stepControl());
  const RunLog log = loop.finish();
  EXPECT_EQ(log.end_reason, RunEnd::Interrupted);
  EXPECT_EQ(log.physics_steps, 50);
  EXPECT_EQ(log.vehicles[0].samples.size(), 25u);
  EXPECT_NEAR(log.sim_time, 0.05, 1e-12);
  EXPECT_EQ(loop.data(), nullptr);
  EXPECT_THROW(loop.finish(), std::logic_error);
}

TEST(SimulationLoop, SnapshotIsTheLogSoFarAndTheRunGoesOn) {
  const Scenario s = test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, 5.0);
  OneQuadrotor q(s);
  SimulationLoop loop(q.world, s, q.no_robots, q.pilots, flightSimulationOptions(flightOptions(s)));
  for (int n = 0; n < 25; ++n) ASSERT_TRUE(loop.stepControl());
  const RunLog early = loop.snapshot();
  EXPECT_EQ(early.end_reason, RunEnd::Running);  // still running
  EXPECT_EQ(early.physics_steps, 50);
  EXPECT_EQ(early.vehicles[0].samples.size(), 25u);
  EXPECT_NEAR(early.sim_time, 0.05, 1e-12);
  EXPECT_GT(early.wall_time, 0.0);

  for (int n = 0; n < 10; ++n) ASSERT_TRUE(loop.stepControl());
  const RunLog log = loop.finish();
  EXPECT_EQ(log.physics_steps, 70);
  ASSERT_EQ(log.vehicles[0].samples.size(), 35u);
  // The snapshot's samples are the first of the finished log, unchanged.
  EXPECT_EQ(log.vehicles[0].samples[24].t, early.vehicles[0].samples[24].t);
  EXPECT_EQ(log.vehicles[0].samples[24].pos, early.vehicles[0].samples[24].pos);
  EXPECT_THROW(loop.snapshot(), std::logic_error);
}

}  // namespace
}  // namespace cosim
