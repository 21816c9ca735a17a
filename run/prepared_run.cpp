#include "run/prepared_run.h"

#include "core/input_error.h"
#include "run/run_evaluation.h"
#include "run/run_files.h"
#include "run/run_simulation.h"
#include "run/team_plan_verification.h"

namespace cosim {

namespace {

RunSetup resolveStage(const Scenario& scenario, const RunRequest& request, RunReporter& report) {
  report.stage(RunStage::Resolve);
  return resolveRun(scenario, request.plan_as_point_mass);
}

// The write and render stages, into the request's folder, from the record. False if the
// interrupt flag stopped the rendering: then there is no index.html and no metrics.json, nothing
// that looks finished.
bool writeRunFolder(PreparedRun& run, const RunRecord& record) {
  const RunRequest& request = run.request;
  RunReporter& report = run.report;
  report.stage(RunStage::Write);
  writeRunLogFiles(request.out_dir, run.scenario, record.log);
  RenderedRun rendered;
  if (run.plan.drivable() && (request.images || request.video)) {
    report.stage(RunStage::Render);
    rendered = renderRunFiles(run.scenario, record, request, report);
    if (rendered.interrupted) return false;
  }
  const std::string no_viewer = writeRunViewerFile(request.out_dir, run.scenario, record);
  if (no_viewer.empty())
    rendered.viewer = "viewer.html";
  else
    report.warning("viewer.html was not written: " + no_viewer);
  finishRunFolder(request.out_dir, run.scenario, record, rendered, request.images);
  return true;
}

}  // namespace

PreparedRun::PreparedRun(const Scenario& s, const RunRequest& r) try
    : scenario(s),
      request(r),
      report(request.observer),
      setup(resolveStage(s, request, report)),
      shared_world(std::make_shared<const WorldModel>(WorldModel::build(s))),
      world(*shared_world) {
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
  // A team's plan is flown before it is trusted, and repaired where it broke.
  if (verifiesTeamPlan(*this)) verified_flight = verifyTeamPlan(*this, plan.verification);
} catch (const InputError& e) {
  throw e.inFile(s.file);  // e.g. a planner's grid too large for the scenario's world
}

RunRecord summarizeRun(const PreparedRun& run, RunLog log) {
  return evaluateRun(run.scenario, run.setup, run.shared_world, run.plan, std::move(log));
}

RunRecord concludeRun(PreparedRun& run, RunLog log) try {
  run.report.stage(RunStage::Evaluate);
  RunRecord record = summarizeRun(run, std::move(log));
  if (record.log.mujoco_warnings > 0)
    run.report.warning("MuJoCo reported " + std::to_string(record.log.mujoco_warnings) +
                       " warning(s); see mujoco_warnings in metrics.json");
  if (!run.request.out_dir.empty() && !writeRunFolder(run, record)) return interruptedRun();
  return record;
} catch (const InputError& e) {
  throw e.inFile(run.scenario.file);  // e.g. a video of more frames than allowed
}

}  // namespace cosim
