#include "experiments/bench/physics_loop.h"

#include <cstdio>

#include "control/cascade_controller.h"
#include "control/waypoint_reference.h"
#include "experiments/bench/bare_replay.h"
#include "sim/flight_simulation.h"
#include "sim/sensors/sensor_presets.h"
#include "sim/world_model.h"

namespace cosim::bench {

namespace {

// A 50 x 50 x 10 m world with 40 obstacles and one quad_1500g that flies across it: the shape
// of the bundled scenarios.
Scenario benchScenario(double seconds) {
  Scenario s;
  s.file = "bench";
  s.world.bounds_min = {0, 0, 0};
  s.world.bounds_max = {50, 50, 10};
  for (int i = 0; i < 40; ++i) {
    Obstacle o;
    o.type = (i % 2) ? ObstacleType::Cylinder : ObstacleType::Box;
    o.pos = {5.0 + (i % 8) * 5.5, 8.0 + (i / 8) * 9.0, 3.0};
    o.size = {2, 2, 6};
    o.radius = 0.8;
    o.height = 6;
    s.world.obstacles.push_back(o);
  }
  VehicleSpec v;
  v.name = "uav1";
  v.model = "quad_1500g";
  v.model_file = modelsDirectory() / "quad_1500g.xml";
  v.start = {2, 2, 8};
  v.waypoints = {{48, 2, 8}, {48, 48, 8}, {2, 48, 8}};
  s.vehicles.push_back(v);
  s.sim.max_time = seconds;
  return s;
}

// The loop against bare mj_step on the same flight of `s`; `target` is the ratio to keep.
Section measureLoop(const Scenario& s, const std::string& name, const std::string& what,
                    double target) {
  const WorldModel world = WorldModel::build(s);

  // Full loop: controller at 500 Hz, logging, contacts.
  CascadeController controller(world.vehicles()[0].params, CascadeGains{});
  std::vector<Eigen::Vector3d> wps = {s.vehicles[0].start};
  for (const auto& w : s.vehicles[0].waypoints) wps.push_back(w);
  WaypointReference reference(wps, 0.0);
  std::vector<VehiclePilot> pilots(1);
  pilots[0].controller = &controller;
  pilots[0].reference = &reference;
  pilots[0].goal = s.vehicles[0].goal();
  FlightOptions options;
  options.settings = s.sim;
  options.hold_after_arrival = 1e9;  // fly for exactly max_time
  const RunLog log = simulateFlight(world, s, pilots, options);

  // Bare engine: the same flight replayed (experiments/bench/bare_replay.h).
  const long steps = log.physics_steps;
  const double bare_s = bareReplaySeconds(world, log, s.sim);

  Section out;
  out.name = name;
  const double bare_rate = steps / bare_s;
  const double loop_rate = log.physics_steps / log.wall_time;
  out.figures = {{"bare_mj_step_steps_per_s", bare_rate, "1/s"},
                 {"full_loop_steps_per_s", loop_rate, "1/s"},
                 {"full_loop_sim_speed", log.sim_time / log.wall_time, "x real time"},
                 {"ratio_full_to_bare", loop_rate / bare_rate, "x"}};
  char ratio[32];
  std::snprintf(ratio, sizeof ratio, "%.2f", target);
  out.note = "quad_1500g in a 40-obstacle world, 1 ms step, control 500 Hz, " + what +
             "; target ratio >= " + ratio + ": " +
             std::string(loop_rate / bare_rate >= target ? "met" : "NOT met");
  return out;
}

}  // namespace

Section benchPhysicsLoop(bool quick) {
  return measureLoop(benchScenario(quick ? 3.0 : 60.0), "physics_loop", "ideal sensing", 0.8);
}

Section benchSensingLoop(bool quick) {
  Scenario s = benchScenario(quick ? 3.0 : 60.0);
  s.sensors = sensorPreset("mocap");
  s.estimator.kind = EstimatorKind::Ekf;
  return measureLoop(s, "sensing_loop",
                     "motion capture (100 Hz pose, 10 ms late) + 500 Hz IMU + error-state EKF",
                     0.6);
}

}  // namespace cosim::bench
