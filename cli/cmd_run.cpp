// cosim run [SCENARIO.yaml]: plan, fly, evaluate and render one scenario.
#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "cli/command.h"
#include "cli/controller_list.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "cli/run_console.h"
#include "core/input_error.h"
#include "core/output_dir_lock.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "run/run_files.h"
#include "run/run_pipeline.h"
#include "run/run_summary_line.h"
#include "run/scenario_checks.h"

namespace cosim::cli {

std::string defaultScenarioPath() {
  return std::string(COSIM_SCENARIOS_DIR) + "/default.yaml";
}

namespace {

struct RunArgs {
  std::string scenario, out;
  bool no_video = false, no_images = false, quiet = false, list_controllers = false;
  long seed = -1;
  double video_speed = 0.0;
  std::vector<std::string> sets;
};

void addRunOptions(CLI::App* cmd, RunArgs& a) {
  cmd->add_option("scenario", a.scenario, "scenario YAML (default: the bundled default scenario)");
  cmd->add_option("--out", a.out, "output folder (default: a new folder under out/)");
  cmd->add_flag("--no-video", a.no_video, "skip video.mp4 (much faster)");
  cmd->add_flag(
      "--no-images", a.no_images,
      "skip final.png, figures/ and index.html too (with --no-video: no rendering at all)");
  cmd->add_option("--seed", a.seed, "random seed (overrides sim.seed)")
      ->check(wholeNumberIn(0L, 2147483647L));
  cmd->add_option("--set", a.sets, "override a scenario key, e.g. --set planner.name=astar")
      ->allow_extra_args(false);
  cmd->add_option("--video-speed", a.video_speed,
                  "time-lapse: simulated seconds per second of video (same as --set "
                  "render.speed=X)")
      ->check(numberIn(0.01, 1000.0));
  cmd->add_flag("--quiet", a.quiet, "no progress lines");
  cmd->add_flag("--list-controllers", a.list_controllers,
                "list every flight controller with its gains (default, valid range, meaning) and "
                "exit");
}

}  // namespace

void addRunCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "run",
      "Plan a path, turn it into a reference, fly it in MuJoCo under the scenario's controller,\n"
      "evaluate it and render it. Writes metrics.json, timeseries.csv, path.csv, final.png and\n"
      "video.mp4 to the output folder. Exit 0 if every vehicle reached its goal without a\n"
      "collision, 1 if not (no path, goal missed, collision), 2 for bad input.\n"
      "`cosim run --list-controllers` lists every flight controller with its gains (name,\n"
      "default, valid range, what it does).");
  auto a = std::make_shared<RunArgs>();
  addRunOptions(cmd, *a);
  cmd->callback([a, &ctx] {
    if (a->list_controllers) {
      std::cout << controllerListText();
      return;
    }
    // Interruptible from here on, loading included. The folder is touched only once the scenario
    // and its planners passed their checks: bad input neither removes an earlier run's results
    // nor leaves an empty folder behind. Then an earlier run's results go (only files cosim can
    // prove it wrote: anything else there is refused) before anything is written, so that
    // neither a failure nor an interruption can leave them looking like this run's.
    const std::atomic<bool>& interrupt = installInterruptFlag();
    RunRequest request;
    checkOutputDir(a->out);
    const std::string path = a->scenario.empty() ? defaultScenarioPath() : a->scenario;
    std::vector<std::string> overrides = a->sets;
    if (a->seed >= 0) overrides.push_back("sim.seed=" + std::to_string(a->seed));
    if (a->video_speed > 0) overrides.push_back("render.speed=" + std::to_string(a->video_speed));
    const Scenario scenario = loadCheckedScenario(path, overrides, PlannerUse::Run);
    RunFolderSession folder(a->out, "--out");
    request.out_dir = folder.dir();
    request.video = !a->no_video;
    request.images = !a->no_images;
    request.interrupt = &interrupt;
    RunConsole console(!a->quiet);
    request.observer = console.observer();
    const RunRecord s = executeRun(scenario, request);
    console.finish();
    folder.finish(s.outcome == RunOutcome::Interrupted);
    if (s.outcome == RunOutcome::Interrupted) {
      std::cerr << "cosim: interrupted; " << printableText(request.out_dir.string())
                << " holds no finished run\n";
      ctx.status = 1;
      return;
    }
    // The record's top-level figures (metrics.json's): for a team, the whole team's.
    // The folder's name is the user's bytes: control characters escaped (core/input_error.h).
    std::cout << "run: " << printableText(request.out_dir.string()) << "\n"
              << "  " << runSummaryLine(s) << "\n";
    if (s.outcome == RunOutcome::TaskFailed)
      std::cerr << "cosim: " << printableText(s.message) << "\n";
    std::cout << printableText(runPagesLine(request.out_dir)) << "\n";
    ctx.status = s.exitStatus();
  });
}

}  // namespace cosim::cli
