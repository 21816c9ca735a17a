#pragma once
// The simulation stage of a run: the simulation loop (sim/simulation_loop.h) over a prepared
// run's world and pilots, with the flight loop's options for quadrotors alone and the ground
// loop's for robots with any quadrotors over them; or, when the plan cannot be driven, an empty
// log that says so (RunEnd::NoPath).
#include <memory>

#include "sim/run_log.h"
#include "sim/simulation_loop.h"

namespace cosim {

struct PreparedRun;

// The loop's options for a prepared run (its plan and pilots made): the request's interrupt
// flag, threads and profile; for robots, the progress in simulated seconds and a navigator's
// decisions before each control step (these call into `run`, which must outlive the loop).
SimulationOptions runLoopOptions(PreparedRun& run);

// Enters the simulation stage, says what is flown or driven, and starts the loop over the
// prepared run's world and pilots with its options (PreparedRun::loop). The run's plan must be
// drivable; `run` must outlive the loop.
std::unique_ptr<SimulationLoop> startRunLoop(PreparedRun& run);

// The whole simulation stage. A navigator's plan is made during the drive: its executed cells
// become the robot's planned_path in the log, and its counters the robots' plan summary.
// Stopped by the request's interrupt flag (RunEnd::Interrupted).
RunLog flyRun(PreparedRun& run);

}  // namespace cosim
