#pragma once
// One run of a scenario, for every front end (the cosim program, sweeps, reproductions, Python)
// and every kind of run (a quadrotor, a quadrotor team, ground robots, robots with quadrotors
// over them, a navigator, given waypoints), in typed stages:
//   prepare (run/prepared_run.h: resolve, run/run_setup.h -> plan, run/run_plan.h -> build
//   pilots, run/run_pilots.h) -> simulate (run/run_simulation.h) -> conclude (evaluate,
//   run/run_evaluation.h, metrics.json from run/metrics_json.h -> write -> render,
//   run/run_files.h).
// The pipeline prints nothing and exits nothing: what it is doing goes to the request's observer
// (run/run_events.h), what it found comes back in the RunSummary.
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "core/json_writer.h"
#include "planning/mapf/mapf_problem.h"
#include "run/run_events.h"
#include "run/scenario_planning.h"
#include "sim/flight_metrics.h"
#include "sim/loop_profile.h"
#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim {

struct RunRequest {
  // Where the run's files go (created beforehand). Empty: no files are written, nothing is
  // rendered and no folder is created; the results are only in the returned RunSummary.
  std::filesystem::path out_dir;
  bool video = true;
  bool images = true;  // final.png, figures/ (and index.html shows them)
  // Told of the stages, progress and warnings as the run goes (none: the run is silent).
  RunObserver observer;
  const std::atomic<bool>* interrupt = nullptr;
  // Plan for a point: ignore the vehicle's size and the margin, as seed 003 did (for its
  // reproduction only; flights planned this way clip obstacles).
  bool plan_as_point_mass = false;
  // A team plan already made for this scenario's robots (cosim mapf --execute prints and writes
  // it first): the robots drive it instead of planning again. It must solve the run's own team
  // instance (same grid cells, starts and goals); the independent validator checks that it does.
  const MapfResult* given_team_plan = nullptr;
  // The simulation loop's threads: 1, or 2 to run the controllers and forces on a second thread
  // during the engine's position stage (sim/simulation_loop.h, SimulationOptions::second_thread;
  // the numbers are the same either way). One by default: on the 2 shared cores measured so far
  // the second thread did not pay (docs/performance.md).
  int loop_threads = 1;
  LoopProfile* profile = nullptr;  // where the loop's time went (sim/loop_profile.h), if given
};

// How a run ended for its front end.
enum class RunOutcome {
  Succeeded,    // every vehicle reached its goal without a collision
  TaskFailed,   // no path, goal missed, collision, a fault (the message says which)
  Interrupted,  // the request's interrupt flag stopped it: nothing finished was written
};

struct RunSummary {
  RunOutcome outcome = RunOutcome::Succeeded;
  std::string message;                 // why the task failed ("" if it succeeded)
  std::vector<FlightMetrics> metrics;  // one per vehicle, in the scenario's order
  double sim_speed_x = 0.0;
  JsonObject metrics_json;  // metrics.json's object (as written into out_dir, if given)
  RunLog log;               // what the simulation recorded (timeseries: sim/run_log_io.h)
  // Each vehicle's plan, in the scenario's order (run/run_plan.h vehiclePlans): what the
  // planner made of it, and for a ground robot its timed plan.
  std::vector<VehiclePlan> plans;

  // The exit status of `cosim run`: 0 if the run succeeded, else 1.
  int exitStatus() const { return outcome == RunOutcome::Succeeded ? 0 : 1; }
};

// prepareRun -> flyRun -> concludeRun (run/prepared_run.h, run/run_simulation.h). The scenario
// is read, never changed. Throws InputError for bad input discovered late (unknown planner, bad
// gains), in the scenario's file. Stopped by the request's interrupt flag (between stages, in
// planning, flight and rendering), it returns interruptedRun() having written no metrics.json or
// index.html.
RunSummary executeRun(const Scenario& scenario, const RunRequest& request);

// Whether the request's interrupt flag is set; what a run stopped by it returns.
bool stopRequestedFor(const RunRequest& request);
RunSummary interruptedRun();

}  // namespace cosim
