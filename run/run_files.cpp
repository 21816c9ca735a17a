#include "run/run_files.h"

#include "core/output_files.h"
#include "render/run_outputs.h"
#include "sim/run_log_io.h"

namespace cosim {

const std::vector<std::string> kRunResultNames = {
    "metrics.json", "index.html", "timeseries.csv", "path.csv", "moving_obstacles.csv",
    "final.png",    "video*.mp4", "figures",        "frames_*"};

bool writeRunFiles(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                   const RunRequest& request, bool render, const JsonObject& metrics,
                   const RunSummary& summary) {
  const auto& dir = request.out_dir;
  if (dir.empty()) return true;  // the caller keeps the run in memory (RunSummary)
  // A folder reused with --out lost an earlier run's results when this run started
  // (kRunResultNames); the marks of a finished run go again in case something wrote them since.
  std::error_code ignored;
  std::filesystem::remove(dir / "metrics.json", ignored);
  std::filesystem::remove(dir / "index.html", ignored);

  writeFileAtomically(dir / "scenario.yaml", scenario.effective_yaml);
  writeFileAtomically(
      dir / "run.json",
      JsonObject().add("scenario_file", std::filesystem::absolute(scenario.file).string()).str() +
          "\n");
  writeFileAtomically(dir / "path.csv", pathCsv(log));
  writeFileAtomically(dir / "timeseries.csv", timeseriesCsv(log));
  if (!log.moving_obstacles.empty())
    writeFileAtomically(dir / "moving_obstacles.csv", movingObstaclesCsv(log));

  // Rendered from the log: final.png, figures/, the videos, and index.html showing them.
  RenderedRun rendered;
  if (render && (request.images || request.video)) {
    RunRenderRequest r;
    r.images = request.images;
    r.video = request.video;
    r.progress = request.progress;
    r.interrupt = request.interrupt;
    rendered = renderRunOutputs(world, scenario, log, dir, r);
    if (rendered.interrupted) return false;
  }
  writeRunReport(dir, scenario, metrics.str(), summary.status == 0 ? "" : summary.message,
                 rendered);
  writeFileAtomically(dir / "metrics.json", metrics.str() + "\n");
  return true;
}

}  // namespace cosim
