#pragma once
// A run made ready to simulate: the prepare stage of run/run_pipeline.h (resolve -> world ->
// plan -> pilots -> the simulation loop's options, with a stop check and an event between
// stages), and the conclude stage that takes the log the loop made (evaluate -> write -> render).
// `cosim run` and cosim.run go prepare -> fly -> conclude through executeRun; Python's
// cosim.Simulation prepares the same way and steps the loop itself (startRunLoop,
// run/run_simulation.h), with the same evaluation for its record (summarizeRun).
#include <memory>
#include <optional>

#include "run/record/run_setup.h"
#include "run/run_pilots.h"
#include "run/run_pipeline.h"
#include "run/run_plan.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/simulation_loop.h"
#include "sim/world_model.h"

namespace cosim {

// The pilots point into the plan and the controllers, and the loop's options into the reporter:
// a PreparedRun stays where it was made (no copies, no moves).
struct PreparedRun {
  // The stages up to the simulation (prepareRun).
  PreparedRun(const Scenario& scenario, const RunRequest& request);
  PreparedRun(const PreparedRun&) = delete;
  PreparedRun& operator=(const PreparedRun&) = delete;

  const Scenario& scenario;  // as loaded: the run reads it, never changes it
  const RunRequest request;
  RunReporter report;  // to request.observer, for every stage of the run
  RunSetup setup;      // the vehicles' groups and their sections, defaults resolved
  // The world, shared with the run's record (run/record/run_record.h).
  const std::shared_ptr<const WorldModel> shared_world;
  const WorldModel& world;
  RunPlan plan;
  RunPilots pilots;
  SimulationOptions loop;  // the simulation loop's (run/run_simulation.h runLoopOptions)
  // A quadrotor team's last verification flight (run/team_plan_verification.h): the loop is
  // deterministic, so it is the run's flight and flyRun does not fly it again.
  std::optional<RunLog> verified_flight;
  // The request's interrupt flag stopped the preparation before it ended (after resolve or
  // plan): plan, pilots and loop are not to be used.
  bool stopped = false;
};

// Resolves, composes the world, plans and builds the pilots. Throws InputError for bad input
// found on the way (unknown planner, bad gains, a grid too large), in the scenario's file: late
// errors get their file here and in concludeRun, not in each front end.
inline PreparedRun prepareRun(const Scenario& scenario, const RunRequest& request) {
  return PreparedRun(scenario, request);
}

// The evaluate stage, silent and writing nothing: the run's record of `log` (a whole run's, or
// a stepped loop's so far; the record keeps it).
RunRecord summarizeRun(const PreparedRun& run, RunLog log);

// The stages after the simulation: evaluate into the run's record, then (with an out_dir) write
// and render from it. Returns interruptedRun() if the interrupt flag stopped the rendering.
// Throws InputError for bad input found while rendering (a video of too many frames), in the
// scenario's file.
RunRecord concludeRun(PreparedRun& run, RunLog log);

}  // namespace cosim
