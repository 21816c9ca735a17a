#pragma once
// The record of one run: what the run was (its setup, resolved once from the scenario), what
// planning made of it, what the simulation logged, and what the evaluation measured, typed.
// Read this first. A run goes
//   Scenario --resolveRun--> RunSetup --plan, fly--> RunLog --evaluate--> RunRecord
// and everything after the evaluation reads the record: metrics.json (run/metrics_json.h, the one
// writer, whose bytes the record's fields fill), the console line (run/run_summary_line.h), the
// pictures, figures, replay page and report (render/), the MCAP export, cosim.run and
// cosim.Simulation.metrics(). Nothing downstream works the setup out again from the Scenario,
// computes a metric again, or parses the JSON the run wrote; `cosim render` and `cosim
// compare-real` read a record back from a run folder with one reader (run/run_folder.h).
//
// Layering: the record's types live in the library cosim_record (this folder, run/record/), which
// depends only on cosim_sim, cosim_planning and cosim_control. The renderer (cosim_render) links
// it to read records; the pipeline (cosim_run, run/) links both and is the only writer of records.
// The scenario a record is of is not in it: the caller holds the Scenario (as loaded, never
// changed) and passes both.
#include <memory>
#include <string>
#include <vector>

#include "run/record/plan_verification_report.h"
#include "run/record/run_metrics.h"
#include "run/record/run_setup.h"
#include "run/record/vehicle_plan.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

// How a run ended for its front end.
enum class RunOutcome {
  Succeeded,    // every vehicle reached its goal without a collision
  TaskFailed,   // no path, goal missed, collision, a fault (the message says which)
  Interrupted,  // the request's interrupt flag stopped it: nothing finished was written
};

// The planner's figures metrics.json reports (the pipeline's RunPlan keeps more).
struct PlanFigures {
  PlanSummary primary;  // of the vehicles the top-level sections drive (RunSetup::primary)
  double robot_inflation = 0.0;
  double quadrotor_inflation = 0.0;
  double cruise_speed_mps = 0.0;                      // the robots' timed plans'
  std::map<std::string, double> trajectory_counters;  // the quadrotors' minimum-snap fits
  PlanVerificationReport verification;                // a quadrotor team's verification flights
};

struct RunRecord {
  RunOutcome outcome = RunOutcome::Succeeded;
  std::string message;  // why the task failed ("" if it succeeded)
  RunSetup setup;       // per vehicle: kind, planning, sections, error reference
  // Each vehicle's plan, in the scenario's order: what the planner made of it, and for a ground
  // robot its timed plan. Empty for vehicles not planned (planning stopped at a failure).
  std::vector<VehiclePlan> plans;
  PlanFigures planning;
  RunMetrics metrics;
  RunLog log;  // what the simulation recorded (timeseries: sim/run_log_io.h)
  // The world the run was composed in (shared with the run that made it).
  std::shared_ptr<const WorldModel> world;

  // The exit status of `cosim run`: 0 if the run succeeded, else 1.
  int exitStatus() const { return outcome == RunOutcome::Succeeded ? 0 : 1; }
  // What vehicle v's tracking error is measured against.
  ErrorReference errorReferenceOf(std::size_t v) const { return setup.vehicles[v].error_reference; }
};

// Where a run's paths come from, for titles and labels: the planner's name, or without a planner
// "given waypoints", "given reference FILE" (one vehicle flying a reference file), "given
// references" (several) or "given waypoints and references" (some of each).
std::string pathSourceName(const Scenario& scenario, const std::string& planner_name);

// Which controller drives the vehicles, as resolved: "<name> controller" when one drives them
// all, else "robots: <name> controller, quadrotors: <name> controller" (quadrotors over ground
// robots fly their own, the `aerial` sections').
std::string vehicleControllers(const RunRecord& record);

// "cosim run: <scenario> (<planner>, <controllers>)": index.html's, viewer.html's and the video's
// title, from the scenario's file name, the top-level planner and vehicleControllers.
std::string runTitle(const Scenario& scenario, const RunRecord& record);

// "Every vehicle reached its goal without a collision." or "The run failed its task: <why>".
std::string runStatusLine(const RunRecord& record);

}  // namespace cosim
