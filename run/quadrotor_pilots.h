#pragma once
// The quadrotors' pilots for a run: each quadrotor's path (run/scenario_planning.h:
// the scenario's planner, or its given waypoints), the reference that path becomes (seed 003's
// waypoint switching, or a minimum-snap trajectory within the airframe's limits) and its flight
// controller (sim/controller_factory.h). Used by `cosim run` for quadrotors and for the
// quadrotors flying over ground robots.
#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "control/flight_controller.h"
#include "control/reference_source.h"
#include "run/run_pipeline.h"
#include "run/scenario_planning.h"
#include "sim/aerial_pilot_step.h"
#include "sim/world_model.h"

namespace cosim {

struct QuadrotorPilots {
  std::vector<VehiclePlan> plans;  // one per quadrotor asked for
  std::vector<std::unique_ptr<ReferenceSource>> references;
  std::vector<std::unique_ptr<FlightController>> controllers;
  // What each quadrotor's flight software believes of its airframe (sim/model_error.h); a deque,
  // so the pilots' pointers into it stay valid.
  std::deque<QuadrotorParams> airframes;
  std::vector<VehiclePilot> pilots;  // filled only when every quadrotor planned and fitted
  bool ready = false;
  std::string failure;  // "no path found: ..." or "no feasible trajectory: ..."
};

// Plans, fits and builds controllers for scenario.vehicles[i] (flying world.vehicles()[i]) for
// each i in `vehicles`, with the scenario's planner, trajectory and controller sections. Throws
// InputError for bad planner, trajectory or controller parameters.
QuadrotorPilots prepareQuadrotorPilots(Scenario& scenario, const WorldModel& world,
                                       const std::vector<std::size_t>& vehicles,
                                       const RunRequest& request);

}  // namespace cosim
