#pragma once
// The pilots stage of a run: a controller for every vehicle (a ground robot's path follower, a
// quadrotor's flight controller, control/controller_factory.h) and, when the plan can be driven,
// the pilots that tie each controller to its plan for the simulation loop.
#include <memory>
#include <vector>

#include "control/flight_controller.h"
#include "control/ground_controller.h"
#include "core/param_set.h"
#include "run/run_plan.h"
#include "sim/aerial_pilot_step.h"
#include "sim/ground_simulation.h"

namespace cosim {

struct RunPilots {
  std::vector<std::unique_ptr<GroundController>> robot_controllers;      // one per robot
  std::vector<std::unique_ptr<FlightController>> quadrotor_controllers;  // one per quadrotor
  // Filled when the plan is drivable, pointing into the plan and the controllers above.
  std::vector<GroundPilot> robots;
  std::vector<VehiclePilot> quadrotors;
};

// The ground robots' controller.gains read as both drives read them (holonomic and differential:
// which one a robot has is known once its model is built), so a gain neither takes, or a value
// out of range, is bad input before planning. Throws InputError.
void checkGroundControllerGains(ParamSet gains);

// Controllers are built even when the plan cannot be driven, so that bad gains are bad input
// whatever the planners found. Throws InputError for bad controller parameters. The pilots
// point into `plan`, which must outlive them.
RunPilots buildPilots(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                      RunPlan& plan);

}  // namespace cosim
