#include "run/prepared_run.h"

#include "core/input_error.h"
#include "run/metrics_json.h"
#include "run/run_evaluation.h"
#include "run/run_files.h"
#include "run/run_simulation.h"

namespace cosim {

namespace {

RunSetup resolveStage(const Scenario& scenario, const RunRequest& request, RunReporter& report) {
  report.stage(RunStage::Resolve);
  return resolveRun(scenario, request.plan_as_point_mass);
}

// The scenario as the pictures and pages describe the run: the renderer reads the controller's
// name (the report's title) and the trajectory mode (what tracking errors are measured against,
// render/log_lookup.h) from a Scenario, so it gets a copy with the sections as resolved.
Scenario describedScenario(const Scenario& scenario, const RunSetup& setup) {
  Scenario described = scenario;
  const MotionSections& primary = setup.primarySections();
  described.motion.controller.name = primary.controller.name;
  described.motion.trajectory.mode = primary.trajectory.mode;
  if (setup.primaryKind() == VehicleKind::GroundRobot)
    described.aerial.trajectory.mode = setup.quadrotor_sections.trajectory.mode;
  return described;
}

// The write and render stages, into the request's folder. False if the interrupt flag stopped
// the rendering: then there is no index.html and no metrics.json, nothing that looks finished.
bool writeRunFolder(PreparedRun& run, const RunLog& log, const RunSummary& summary) {
  const RunRequest& request = run.request;
  RunReporter& report = run.report;
  report.stage(RunStage::Write);
  writeRunLogFiles(request.out_dir, run.scenario, log);
  const Scenario described = describedScenario(run.scenario, run.setup);
  RenderedRun rendered;
  if (run.plan.drivable() && (request.images || request.video)) {
    report.stage(RunStage::Render);
    rendered = renderRunFiles(run.world, described, log, request, report);
    if (rendered.interrupted) return false;
  }
  const std::string failure = summary.message;
  const std::string no_viewer =
      writeRunViewerFile(request.out_dir, run.world, described, log, failure);
  if (no_viewer.empty())
    rendered.viewer = "viewer.html";
  else
    report.warning("viewer.html was not written: " + no_viewer);
  finishRunFolder(request.out_dir, described, summary.metrics_json, failure, rendered,
                  request.images);
  return true;
}

}  // namespace

PreparedRun::PreparedRun(const Scenario& s, const RunRequest& r) try
    : scenario(s),
      request(r),
      report(request.observer),
      setup(resolveStage(s, request, report)),
      world(WorldModel::build(s)) {
  if (stopRequestedFor(request)) {
    stopped = true;
    return;
  }
  report.stage(RunStage::Plan);
  plan = planRun(scenario, setup, world, request, report);
  // A stop during planning ends the planners early: their "no path" is not a result.
  if (stopRequestedFor(request)) {
    stopped = true;
    return;
  }
  report.stage(RunStage::BuildPilots);
  pilots = buildPilots(scenario, setup, world, plan);
  loop = runLoopOptions(*this);
} catch (const InputError& e) {
  throw e.inFile(s.file);  // e.g. a planner's grid too large for the scenario's world
}

RunSummary summarizeRun(const PreparedRun& run, const RunLog& log) {
  const RunMetrics metrics = evaluateRun(run.scenario, run.setup, run.world, run.plan, log);
  RunSummary summary;
  summary.outcome = metrics.status == 0 ? RunOutcome::Succeeded : RunOutcome::TaskFailed;
  summary.message = metrics.message;
  summary.metrics = metrics.vehicles;
  summary.sim_speed_x = metrics.sim_speed_x;
  summary.metrics_json =
      runMetricsJson({run.scenario, run.setup, run.world, run.plan, metrics, log});
  summary.plans = vehiclePlans(run.scenario, run.setup, run.plan);
  return summary;
}

RunSummary concludeRun(PreparedRun& run, RunLog log) try {
  run.report.stage(RunStage::Evaluate);
  RunSummary summary = summarizeRun(run, log);
  if (log.mujoco_warnings > 0)
    run.report.warning("MuJoCo reported " + std::to_string(log.mujoco_warnings) +
                       " warning(s); see mujoco_warnings in metrics.json");
  if (!run.request.out_dir.empty() && !writeRunFolder(run, log, summary)) return interruptedRun();
  summary.log = std::move(log);
  return summary;
} catch (const InputError& e) {
  throw e.inFile(run.scenario.file);  // e.g. a video of more frames than allowed
}

}  // namespace cosim
