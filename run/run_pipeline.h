#pragma once
// One run of a scenario, for every front end (the cosim program, sweeps, reproductions, Python)
// and every kind of run (a quadrotor, a quadrotor team, ground robots, robots with quadrotors
// over them, a navigator, given waypoints), in typed stages:
//   prepare (run/prepared_run.h: resolve, run/record/run_setup.h -> plan, run/run_plan.h ->
//   build pilots, run/run_pilots.h) -> simulate (run/run_simulation.h) -> conclude (evaluate,
//   run/run_evaluation.h, into the run's record, run/record/run_record.h -> write, metrics.json
//   from the record by run/metrics_json.h -> render from the record, run/run_files.h).
// The pipeline prints nothing and exits nothing: what it is doing goes to the request's observer
// (run/run_events.h), what it found comes back in the run's record (run/record/run_record.h).
#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "planning/mapf/mapf_problem.h"
#include "run/record/run_record.h"
#include "run/run_events.h"
#include "sim/loop_profile.h"
#include "sim/scenario.h"

namespace cosim {

struct RunRequest {
  // Where the run's files go (created beforehand). Empty: no files are written, nothing is
  // rendered and no folder is created; the results are only in the returned RunRecord.
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

// prepareRun -> flyRun -> concludeRun (run/prepared_run.h, run/run_simulation.h). The scenario
// is read, never changed. Throws InputError for bad input discovered late (unknown planner, bad
// gains), in the scenario's file. Stopped by the request's interrupt flag (between stages, in
// planning, flight and rendering), it returns interruptedRun() having written no metrics.json or
// index.html.
RunRecord executeRun(const Scenario& scenario, const RunRequest& request);

// Whether the request's interrupt flag is set; what a run stopped by it returns.
bool stopRequestedFor(const RunRequest& request);
RunRecord interruptedRun();

}  // namespace cosim
