#pragma once
// For simulation tests: one vehicle in an empty 20 x 20 x 10 m world, flying from `start` to
// `goal` for at most `seconds` of simulated time. (cascade_flight_test.cpp and
// disturbances_test.cpp build the same scenario by hand and could use this.)
#include <string>

#include "sim/scenario.h"

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

}  // namespace cosim::test
