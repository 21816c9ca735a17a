#include "run/run_files.h"

#include "core/atomic_file.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "render/run_outputs.h"
#include "render/viewer_page.h"
#include "run/metrics_json.h"
#include "run/run_pipeline.h"
#include "sim/run_log_io.h"

namespace cosim {

const std::vector<std::string> kRunResultNames = {
    "metrics.json", "index.html", "viewer.html", "timeseries.csv", "path.csv",
    "moving_obstacles.csv", "final.png", "video*.mp4", "figures", "frames_*",
    // The copies of the references flown (runReferenceCopyName).
    "reference_*.csv",
    // A comparison with a real flight (cosim compare-real) was of the run this one replaces.
    "compare.*"};

const std::vector<std::string> kRunReplacedNames = {"scenario.yaml", "run.json"};

void clearRunFolder(const std::filesystem::path& dir, const std::string& option) {
  for (const std::string& name : kRunReplacedNames) requireCosimOutput(dir / name, option);
  removeStaleResults(dir, kRunResultNames, option);
}

RunFolderSession::RunFolderSession(const std::string& out, const std::string& option) {
  if (!out.empty() && std::filesystem::is_directory(out)) {
    lock_.acquire(out, option);
    clearRunFolder(out, option);
  }
  dir_ = prepareOutputDir(out, "run");
  lock_.acquire(dir_, option);
  manifest_.emplace(dir_, "run");
}

void writeRunLogFiles(const std::filesystem::path& dir, const Scenario& scenario,
                      const RunLog& log) {
  // A folder reused with --out lost an earlier run's results when this run started
  // (clearRunFolder); the marks of a finished run go again in case cosim wrote them since (a
  // file of anyone else's there refuses the run).
  removeStaleResults(dir, {"metrics.json", "index.html"});

  writeFileAtomically(dir / "scenario.yaml", scenario.effective_yaml);
  // The references flown, as read: the run renders again after their files moved.
  for (std::size_t i = 0; i < scenario.vehicles.size(); ++i)
    if (const auto& text = scenario.vehicles[i].reference_text)
      writeFileAtomically(dir / runReferenceCopyName(i), *text);
  // The rows of the logs, for cosim render to tell a complete log from one cut at a line
  // boundary, and how the run ended (only a run that diverged logs numbers that are not finite).
  long timeseries_rows = 0, path_rows = 0;
  for (const VehicleLog& v : log.vehicles) {
    timeseries_rows += static_cast<long>(v.samples.size());
    path_rows += static_cast<long>(v.planned_path.size());
  }
  writeFileAtomically(
      dir / "run.json",
      JsonObject()
              .add("scenario_file", std::filesystem::absolute(scenario.file).string())
              .add("timeseries_rows", timeseries_rows)
              .add("path_rows", path_rows)
              .add("end_reason", runEndName(log.end_reason))
              .str() +
          "\n");
  writeFileAtomically(dir / "path.csv", pathCsv(log));
  writeFileAtomically(dir / "timeseries.csv", timeseriesCsv(log));
  if (!log.moving_obstacles.empty())
    writeFileAtomically(dir / "moving_obstacles.csv", movingObstaclesCsv(log));
}

RenderedRun renderRunFiles(const Scenario& scenario, const RunRecord& record,
                           const RunRequest& request, const RunReporter& report) {
  RunRenderRequest r;
  r.images = request.images;
  r.video = request.video;
  r.interrupt = request.interrupt;
  r.on_message = [&report](const std::string& line) { report.message(line); };
  r.on_progress = [&report](const std::string& what, int done, int total) {
    report.progress(what, done, total);
  };
  r.on_warning = [&report](const std::string& text) { report.warning(text); };
  return renderRunOutputs(scenario, record, request.out_dir, r);
}

std::string writeRunViewerFile(const std::filesystem::path& dir, const Scenario& scenario,
                               const RunRecord& record) {
  return writeRunViewer(dir, *record.world, scenario, record.log, runTitle(scenario, record),
                        runStatusLine(record), &record);
}

void finishRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                     const RunRecord& record, const RenderedRun& rendered, bool report_page) {
  const JsonObject metrics = runMetricsJson(scenario, record);
  if (report_page) writeRunReport(dir, scenario, record, metrics, rendered);
  writeFileAtomically(dir / "metrics.json", metrics.str() + "\n");
}

}  // namespace cosim
