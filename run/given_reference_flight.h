#pragma once
// One quadrotor flying a reference in time under a controller section, as `cosim run` flies it,
// without the plan stage: for the studies and benchmarks that fly the same reference many times
// on one composed world. The controller comes from the run's resolved sections
// (run/record/run_setup.h), never from the scenario's fields directly.
#include "sim/aerial_pilot_step.h"
#include "sim/flight_simulation.h"
#include "sim/motion_sections.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// What one quadrotor flies: `reference` (a reference in time) to `goal`; reference_end: when a
// given reference ends (negative: none, the goal ends the run).
struct ReferenceFlight {
  ReferenceSource* reference = nullptr;
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  double reference_end = -1.0;
};

// The scenario's first vehicle flies `flight` under `controller`. `world` must be composed from
// `scenario` (or a variant of its model). Throws InputError for bad controller gains.
RunLog flyReference(const Scenario& scenario, const WorldModel& world,
                    const ControllerSection& controller, const ReferenceFlight& flight,
                    const FlightOptions& options);

// The scenario's first vehicle flies its given reference (`vehicles[0].reference`, which it must
// have) under the controller section the run resolves for it.
RunLog flyGivenReference(const Scenario& scenario, const WorldModel& world,
                         const FlightOptions& options);

}  // namespace cosim
