#pragma once
// The bare engine on a flight the full loop has flown: the same model replaying the rotor
// thrusts the loop applied (logged at each control step, held over the control period), so that
// it integrates the same motion (same contacts, same work per step) with no controller,
// estimator, logging or bookkeeping. What the loop's bench sections compare against.
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim::bench {

// Wall-clock seconds of log.physics_steps bare mj_step calls replaying log.vehicles[0]'s
// thrusts on `world` (the world the log was flown in, `sim` its settings). With
// `follow_logged_state` the vehicle is also put back on the logged state at each control step
// (a write of 13 numbers): an open-loop replay of a small, agile airframe drifts off the flight
// within seconds (into the floor, where contacts make each step dearer), so only this keeps the
// bare engine on the same motion over a long flight.
double bareReplaySeconds(const WorldModel& world, const RunLog& log, const SimSettings& sim,
                         bool follow_logged_state = false);

}  // namespace cosim::bench
