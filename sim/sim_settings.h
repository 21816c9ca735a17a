#pragma once
// What a scenario's `sim:` section asks for: the physics step, the control rate, the run's
// length, the seed and when a goal counts as reached (sim/scenario_sim_settings.cpp reads it
// and checks the rest of the scenario against it).
#include <cstdint>

namespace cosim {

struct SimSettings {
  double timestep = 0.001;    // s, physics step
  double control_rate = 500;  // Hz, controller rate; the physics rate must be a multiple
  double max_time = 120.0;    // s of simulated time before giving up
  std::uint64_t seed = 1;
  double goal_tolerance = 0.2;  // m: the goal is reached within this distance (seed 003: 0.2 m)

  // The keys (sim/declared_keys.h). A step above 20 ms cannot hold a quadrotor's attitude loop.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("timestep", timestep, 1e-5, 0.02, "s, the physics step");
    v.number("control_rate", control_rate, 1.0, 10000.0,
             "Hz, the controller's rate; the physics rate (1/timestep) must be a whole multiple");
    v.number("max_time", max_time, 0.01, 86400.0, "s of simulated time before the run gives up");
    v.integer("seed", seed, 0, 2147483647L, "the seed of every random stream of the run");
    v.number("goal_tolerance", goal_tolerance, 0.01, 100.0,
             "m: a vehicle within this distance of its goal has reached it");
  }
};

}  // namespace cosim
