#pragma once
// For simulation tests: one vehicle in an empty 20 x 20 x 10 m world, flying from `start` to
// `goal` for at most `seconds` of simulated time, and a flight of it under a given controller.
#include <memory>
#include <string>

#include "control/waypoint_reference.h"
#include "sim/flight_simulation.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim::test {

inline Scenario singleVehicleScenario(const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                                      double seconds, const std::string& model = "quad_1500g") {
  Scenario s;
  s.file = "test";
  s.world.bounds_min = {-10, -10, 0};
  s.world.bounds_max = {10, 10, 10};
  VehicleSpec v;
  v.name = "uav1";
  v.model = model;
  v.model_file = modelsDirectory() / (model + ".xml");
  v.start = start;
  v.waypoints = {goal};
  s.vehicles.push_back(v);
  s.sim.max_time = seconds;
  return s;
}

// Flies vehicle 0 of `s` for the whole sim.max_time (arrival does not end the run; only a fault
// does) with its goal as the set-point, under the controller `make(params)` builds from the
// model's parameters.
template <class MakeController>
RunLog flyWholeTime(const Scenario& s, MakeController make) {
  const WorldModel world = WorldModel::build(s);
  std::unique_ptr<FlightController> controller = make(world.vehicles()[0].params);
  WaypointReference reference({s.vehicles[0].goal()}, 0.0);
  std::vector<VehiclePilot> pilots(1);
  pilots[0].controller = controller.get();
  pilots[0].reference = &reference;
  pilots[0].goal = s.vehicles[0].goal();
  FlightOptions options;
  options.settings = s.sim;
  options.hold_after_arrival = 1e9;
  return simulateFlight(world, s, pilots, options);
}

}  // namespace cosim::test
