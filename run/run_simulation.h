#pragma once
// The simulation stage of a run: the flight loop for quadrotors alone (sim/flight_simulation.h),
// the ground loop for robots with any quadrotors over them (sim/ground_simulation.h), or, when
// the plan cannot be driven, an empty log that says so (end_reason "no_path").
#include "run/run_events.h"
#include "run/run_pilots.h"
#include "run/run_plan.h"
#include "sim/run_log.h"

namespace cosim {

struct RunRequest;

// A navigator's plan is made during the drive: its executed cells become the robot's
// planned_path in the log, and its counters the robots' plan summary. Stopped by the request's
// interrupt flag (end_reason "interrupted").
RunLog simulateRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                   RunPlan& plan, RunPilots& pilots, const RunRequest& request,
                   const RunReporter& report);

}  // namespace cosim
