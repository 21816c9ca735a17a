#include "run/run_pipeline.h"

#include "run/metrics_json.h"
#include "run/run_evaluation.h"
#include "run/run_files.h"
#include "run/run_pilots.h"
#include "run/run_plan.h"
#include "run/run_setup.h"
#include "run/run_simulation.h"
#include "sim/world_model.h"

namespace cosim {

namespace {

// The write and render stages, into the request's folder. False if the interrupt flag stopped
// the rendering: then there is no index.html and no metrics.json, nothing that looks finished.
bool writeRunFolder(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                    const RunRequest& request, RunReporter& report, bool render,
                    const RunSummary& summary) {
  report.stage(RunStage::Write);
  writeRunLogFiles(request.out_dir, scenario, log);
  RenderedRun rendered;
  if (render && (request.images || request.video)) {
    report.stage(RunStage::Render);
    rendered = renderRunFiles(world, scenario, log, request, report);
    if (rendered.interrupted) return false;
  }
  const std::string failure = summary.status == 0 ? "" : summary.message;
  const std::string no_viewer = writeRunViewerFile(request.out_dir, world, scenario, log, failure);
  if (no_viewer.empty())
    rendered.viewer = "viewer.html";
  else
    report.warning("viewer.html was not written: " + no_viewer);
  finishRunFolder(request.out_dir, scenario, summary.metrics_json, failure, rendered);
  return true;
}

}  // namespace

bool stopRequestedFor(const RunRequest& request) {
  return request.interrupt && request.interrupt->load();
}

RunSummary interruptedRun() {
  RunSummary s;
  s.status = 1;
  s.message = "interrupted";
  return s;
}

RunSummary executeRun(Scenario& scenario, const RunRequest& request) {
  RunReporter report(request.observer);
  report.stage(RunStage::Resolve);
  const RunSetup setup = resolveRun(scenario, request.plan_as_point_mass);
  const WorldModel world = WorldModel::build(scenario);
  if (stopRequestedFor(request)) return interruptedRun();

  report.stage(RunStage::Plan);
  RunPlan plan = planRun(scenario, setup, world, request, report);
  // A stop during planning ends the planners early: their "no path" is not a result.
  if (stopRequestedFor(request)) return interruptedRun();
  report.stage(RunStage::BuildPilots);
  RunPilots pilots = buildPilots(scenario, setup, world, plan);

  report.stage(RunStage::Simulate);
  RunLog log = simulateRun(scenario, setup, world, plan, pilots, request, report);
  if (runEndOf(log.end_reason) == RunEnd::Interrupted) return interruptedRun();

  report.stage(RunStage::Evaluate);
  const RunMetrics metrics = evaluateRun(scenario, setup, world, plan, log);
  if (log.mujoco_warnings > 0)
    report.warning("MuJoCo reported " + std::to_string(log.mujoco_warnings) +
                   " warning(s); see mujoco_warnings in metrics.json");
  RunSummary summary;
  summary.status = metrics.status;
  summary.message = metrics.message;
  summary.metrics = metrics.vehicles;
  summary.sim_speed_x = metrics.sim_speed_x;
  summary.metrics_json = runMetricsJson({scenario, setup, world, plan, metrics, log});
  summary.plans = vehiclePlans(scenario, setup, plan);
  if (!request.out_dir.empty() &&
      !writeRunFolder(world, scenario, log, request, report, plan.drivable(), summary))
    return interruptedRun();
  summary.log = std::move(log);
  return summary;
}

}  // namespace cosim
