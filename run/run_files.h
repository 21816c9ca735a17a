#pragma once
// The files of a run, written in an order that never lets an unfinished run look finished: first
// any metrics.json and index.html of an earlier run in the folder go, then the log files
// (scenario.yaml, run.json, path.csv, timeseries.csv, moving_obstacles.csv), the pictures and
// videos rendered from the log, index.html, and metrics.json last: its presence means the run's
// files are complete.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/json_writer.h"
#include "core/output_dir_lock.h"
#include "core/output_manifest.h"
#include "render/run_outputs.h"
#include "run/record/run_record.h"
#include "run/run_events.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

struct RunRequest;

// What `cosim run` writes into its folder that says "a run happened" (everything but the copy of
// the scenario, which may be the very file being run): removed before the run starts.
extern const std::vector<std::string> kRunResultNames;
// What a run replaces in its folder without removing it first (scenario.yaml, run.json).
extern const std::vector<std::string> kRunReplacedNames;

// Readies `dir` for a run once its inputs are checked: refuses (InputError naming the file) if
// any name a run writes holds a file cosim cannot prove it wrote (core/output_manifest.h), else
// removes kRunResultNames.
void clearRunFolder(const std::filesystem::path& dir, const std::string& option = "--out");

// The folder of one run, for `cosim run` and cosim.run alike, made ready once the scenario and
// its planners passed their checks (bad input neither removes an earlier run's results nor
// leaves an empty folder behind; checkOutputDir, core/output_files.h, checks `out` before the
// scenario is loaded): locked (core/output_dir_lock.h) before an earlier run's results go
// (clearRunFolder: only files cosim can prove it wrote), created (a new folder under out/ for an
// empty `out`), and what the run writes recorded in its manifest, last, however it ends. Throws
// InputError naming `option` for a folder that cannot be used.
class RunFolderSession {
 public:
  RunFolderSession(const std::string& out, const std::string& option);
  RunFolderSession(const RunFolderSession&) = delete;
  RunFolderSession& operator=(const RunFolderSession&) = delete;

  const std::filesystem::path& dir() const { return dir_; }
  // The manifest's state: "complete", or "unfinished" for an interrupted run.
  void finish(bool interrupted) { manifest_->finish(interrupted ? "unfinished" : "complete"); }

 private:
  OutputDirLock lock_;  // released after the manifest is written
  std::filesystem::path dir_;
  std::optional<OutputManifestScope> manifest_;
};

// The write stage: the log's files in `dir`, once an earlier run's finishing marks are gone.
void writeRunLogFiles(const std::filesystem::path& dir, const Scenario& scenario,
                      const RunLog& log);

// The render stage: final.png, figures/ and the videos the request asks for, into its out_dir,
// from the record. Returns with `interrupted` set if the request's interrupt flag stopped it.
RenderedRun renderRunFiles(const Scenario& scenario, const RunRecord& record,
                           const RunRequest& request, const RunReporter& report);

// The replay stage: dir/viewer.html (render/viewer_page.h). Returns "" when written, else why
// not (three.js is missing), for the front end to say once; the run goes on without it.
std::string writeRunViewerFile(const std::filesystem::path& dir, const Scenario& scenario,
                               const RunRecord& record);

// The finishing marks: index.html (showing `rendered`; only with `report_page`: --no-images
// writes no page), then metrics.json, written from the record (run/metrics_json.h).
void finishRunFolder(const std::filesystem::path& dir, const Scenario& scenario,
                     const RunRecord& record, const RenderedRun& rendered, bool report_page);

}  // namespace cosim
