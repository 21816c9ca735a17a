#pragma once
// One quadrotor flying its scenario's given reference (`vehicles[0].reference`) under the
// scenario's controller, as `cosim run` flies it, without the plan stage: for the studies and
// benchmarks that fly the same reference many times on one composed world.
#include "sim/flight_simulation.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// `world` must be composed from `scenario` (or a variant of its model); the scenario's first
// vehicle must have a reference. Throws InputError for bad controller gains.
RunLog flyGivenReference(const Scenario& scenario, const WorldModel& world,
                         const FlightOptions& options);

}  // namespace cosim
