#pragma once
// A run of ground robots (URDF bases, sim/urdf_vehicle.h), and of quadrotors flying over them,
// to its end: sim/simulation_loop.h stepped until it stops. Each robot's controller at the
// control rate follows its timed path (sim/ground_pilot_step.h), moving obstacles (mocap bodies)
// are placed every physics step, and contacts are booked (the floor under a ground robot is not a
// collision). Quadrotors fly through sim/aerial_pilot_step.h and are logged at the robots'
// instants (at most log_rate samples a second).
#include <vector>

#include "sim/aerial_pilot_step.h"
#include "sim/ground_pilot_step.h"
#include "sim/run_log.h"
#include "sim/simulation_loop.h"
#include "sim/world_model.h"

namespace cosim {

// Its defaults are a ground run's: robots hold their goal 0.5 s, the log has 50 samples a second.
using GroundSimOptions = SimulationOptions;

// Runs until every vehicle has reached its goal and held it, max_time, an interrupt, divergence
// (a NaN state, a quadrotor far outside the world), "unstable" (MuJoCo found bad numbers),
// "saturated" (a quadrotor's mixer), or before_control giving up. `robots` are the world's ground
// robots in order, `quadrotors` its other vehicles in order (the log keeps the world's order).
RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& robots, std::vector<VehiclePilot>& quadrotors,
                      const GroundSimOptions& options);
// A world of ground robots only.
RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& pilots, const GroundSimOptions& options);

}  // namespace cosim
