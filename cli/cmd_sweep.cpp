// cosim sweep SWEEP.yaml: run an experiment grid headless, in parallel, resumable and shardable.
#include <sched.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_dir_lock.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "experiments/sweep/sweep_identity.h"
#include "experiments/sweep/sweep_jobs.h"
#include "experiments/sweep/sweep_outputs.h"
#include "experiments/sweep/sweep_runner.h"
#include "experiments/sweep/sweep_shard.h"
#include "experiments/sweep/sweep_spec.h"

namespace cosim::cli {

namespace {

// Cores this process may use (affinity masks and Slurm allocations included).
int availableCores() {
  if (const char* slurm = std::getenv("SLURM_CPUS_PER_TASK"); slurm && std::atoi(slurm) > 0)
    return std::atoi(slurm);
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  return std::max(1u, std::thread::hardware_concurrency());
}

std::string fileText(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

struct SweepArgs {
  std::string sweep, out, shard = "1/1";
  int jobs = 0;
  bool merge_only = false, quiet = false;
};

// One sweep at a time in the folder: its shards together (each shard once), or the whole sweep
// or a merge alone (core/output_dir_lock.h). Each job's `cosim run` locks its own job folder as
// well.
void lockSweepFolder(const SweepArgs& a, const SweepShard& shard, const std::filesystem::path& out,
                     OutputDirLock& sweep_lock, OutputDirLock& shard_lock) {
  const bool sharded = !shard.whole() && !a.merge_only;
  sweep_lock.acquire(out, "--out",
                     sharded ? OutputDirLock::Mode::Shared : OutputDirLock::Mode::Exclusive);
  if (sharded)
    shard_lock.acquire(out, "--out", OutputDirLock::Mode::Exclusive,
                       ".cosim-shard-" + std::to_string(shard.index) + "-of-" +
                           std::to_string(shard.count) + ".lock");
}

// Runs the shard's unfinished jobs; returns 1 if they were interrupted, else 0.
int runShardJobs(const SweepArgs& a, const SweepSpec& spec, const SweepShard& shard,
                 const std::vector<SweepJob>& jobs, const std::filesystem::path& out,
                 const std::atomic<bool>& interrupt) {
  SweepRunOptions o;
  o.out_dir = out;
  o.jobs = a.jobs > 0 ? a.jobs : availableCores();
  o.shard = shard;
  o.video = spec.video;
  o.job_timeout_s = spec.job_timeout_s;
  o.kill_grace_s = spec.kill_grace_s;
  o.progress = !a.quiet;
  o.interrupt = &interrupt;
  const SweepRunReport r = runSweepJobs(jobs, o);
  if (!r.interrupted) return 0;
  std::cerr << "cosim: sweep interrupted: " << r.unfinished
            << " job(s) left unfinished; run the same command again to resume\n";
  return 1;
}

// The merged tables and figure, and what the user must know about them; returns the exit
// status (`status`, or 1 when --merge-only finds jobs missing).
int mergeSweep(const SweepArgs& a, const SweepSpec& spec, const std::vector<SweepJob>& jobs,
               const std::filesystem::path& out, int status, OutputManifestScope& manifest) {
  const SweepOutputs merged = writeSweepOutputs(spec, jobs, out);
  std::cout << "sweep: " << out.string() << "\n  "
            << (merged.unfinished ? "results.partial.csv" : "results.csv") << ": " << merged.rows
            << " of " << jobs.size() << " jobs"
            << (merged.unfinished ? " (" + std::to_string(merged.unfinished) +
                                        " unfinished: the sweep is " + merged.state + ")"
                                  : "")
            << "\n";
  if (merged.program_builds > 1)
    std::cerr << "sweep: warning: the results come from " << merged.program_builds
              << " different builds of cosim (the sweep was resumed after a rebuild); delete "
              << (out / "jobs").string() << " to rerun every job with this one\n";
  if (!merged.figure_problem.empty())
    std::cerr << "sweep: no figure.png: " << merged.figure_problem << "\n";
  if (a.merge_only && merged.unfinished > 0) status = 1;
  manifest.finish(merged.state);
  return status;
}

// The command: lock the folder, run the shard's jobs (unless --merge-only), merge (unless only
// one shard of several ran); the exit status goes into ctx.status.
void runSweep(const SweepArgs& a, CommandContext& ctx) {
  const std::atomic<bool>& interrupt = installInterruptFlag();
  const SweepSpec spec = loadSweepSpec(a.sweep);
  const SweepShard shard =
      parseSweepShard(a.shard, [](const char* name) -> const char* { return std::getenv(name); });
  const std::filesystem::path out =
      prepareOutputDir(a.out.empty() ? "out/sweep-" + spec.name : a.out, "sweep");
  OutputDirLock sweep_lock, shard_lock;
  lockSweepFolder(a, shard, out, sweep_lock, shard_lock);
  // A folder holding another sweep is refused before anything in it changes
  // (experiments/sweep/sweep_identity.h); what this one writes is recorded in the folder's
  // manifest, last, with the sweep's state (core/output_manifest.h).
  checkSweepFolderHoldsThisSweep(spec, out);
  OutputManifestScope manifest(out, "sweep");
  const std::vector<SweepJob> jobs = expandSweepJobs(spec, out);
  // A copy of the sweep file beside its results (same text from every shard).
  const std::string text = fileText(spec.file);
  if (fileText(out / "sweep.yaml") != text) writeFileAtomically(out / "sweep.yaml", text);

  int status = 0;
  if (!a.merge_only) {
    // The merged tables of an earlier invocation go before any job runs: until this one merges
    // again, nothing in the folder may present a result whose inputs have since changed.
    removeStaleResults(out, {"results.csv", "summary.csv", "figure.png", "figure.svg",
                             "results.partial.csv", "summary.partial.csv"});
    std::vector<SweepJob> mine;
    for (const auto& j : jobs)
      if (shard.owns(j.id)) mine.push_back(j);
    validateSweepJobs(spec, mine);
    if (interrupt.load()) {
      std::cerr << "cosim: sweep interrupted before its jobs started; run the same command "
                   "again to start it\n";
      ctx.status = 1;
      return;
    }
    status = runShardJobs(a, spec, shard, jobs, out, interrupt);
    if (!shard.whole()) {
      if (!a.quiet)
        std::cerr << "sweep: shard " << shard.index << "/" << shard.count
                  << " done; when every shard is, merge with: cosim sweep " << a.sweep
                  << " --merge-only --out " << out.string() << "\n";
      manifest.finish("shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
                      (status ? " interrupted" : " done"));
      ctx.status = status;
      return;
    }
  }
  ctx.status = mergeSweep(a, spec, jobs, out, status, manifest);
}

}  // namespace

void addSweepCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "sweep",
      "Run an experiment grid headless: every scenario (or generated world) of SWEEP.yaml times\n"
      "every combination of its `vary:` values is one job, run as a separate `cosim run` process,\n"
      "--jobs at a time. Writes DIR/jobs/<id>/ (each job's files and result.json), then\n"
      "DIR/results.csv (one row per job, by job id), DIR/summary.csv (mean, sd, median, 95% CI "
      "per\n"
      "group of seeds) and DIR/figure.png. Re-running skips finished jobs. Scenario paths in the\n"
      "sweep file are relative to its folder, else to the current directory. Exit 0 when every\n"
      "job (of the shard) has a result, whatever its status; 1 if interrupted or, with\n"
      "--merge-only, if jobs are missing; 2 for bad input. Format: experiments/sweeps/example.yaml "
      "(commented).");
  auto a = std::make_shared<SweepArgs>();
  cmd->add_option("sweep", a->sweep, "sweep YAML file")->required();
  cmd->add_option("--jobs", a->jobs, "jobs run in parallel (default: the available cores)")
      ->check(wholeNumberIn(1, 4096));
  cmd->add_option("--shard", a->shard,
                  "run only slice I of N (I/N, 1-based; 'auto' takes it from Slurm's\n"
                  "SLURM_ARRAY_TASK_ID/MIN/COUNT); merge afterwards with --merge-only");
  cmd->add_option("--out", a->out, "output folder (default: out/sweep-<sweep name>)");
  cmd->add_flag("--merge-only", a->merge_only, "only merge finished jobs into results.csv");
  cmd->add_flag("--quiet", a->quiet, "no progress lines");
  cmd->callback([a, &ctx] { runSweep(*a, ctx); });
}

}  // namespace cosim::cli
