#pragma once
// Runs a sweep's jobs (those of one shard) as parallel child processes `cosim run SCENARIO --out
// JOBDIR --quiet [--no-video] --set k=v...`, at most `jobs` at a time. A job that crashes, hangs
// past its time limit (SIGTERM, then SIGKILL after a grace period) or fails its task is recorded
// as such and the sweep goes on. Finished jobs (JOBDIR/result.json with a matching fingerprint)
// are skipped, so re-running a sweep resumes it. On interrupt, running jobs are stopped and left
// unfinished; finished results stay.
#include <atomic>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "experiments/sweep/sweep_jobs.h"
#include "experiments/sweep/sweep_shard.h"

namespace cosim {

struct SweepRunOptions {
  std::filesystem::path out_dir;  // jobs go to out_dir/jobs/<id>/
  int jobs = 1;                   // parallel processes
  SweepShard shard;
  std::string program = "/proc/self/exe";  // the cosim binary that runs each job
  bool video = false;
  double job_timeout_s = 600.0;
  double kill_grace_s = 5.0;
  bool progress = true;  // progress lines on stderr
  const std::atomic<bool>* interrupt = nullptr;
};

struct SweepRunReport {
  std::size_t in_shard = 0;
  std::size_t already_finished = 0;             // skipped: finished by an earlier invocation
  std::size_t ran = 0;                          // finished now
  std::size_t unfinished = 0;                   // left for a later invocation (interrupt)
  std::map<std::string, std::size_t> statuses;  // of the jobs finished now
  bool interrupted = false;
  double wall_time_s = 0.0;
};

// The folder of a job.
std::filesystem::path sweepJobDir(const std::filesystem::path& out_dir, const SweepJob& job,
                                  std::size_t job_count);
// The `cosim run` arguments of one job writing into `dir` (without video: no pictures at all).
std::vector<std::string> sweepJobArguments(const SweepJob& job, const std::filesystem::path& dir,
                                           bool video);
// True if the job's result.json exists and was made for this job (same fingerprint).
bool sweepJobFinished(const std::filesystem::path& job_dir, const SweepJob& job);

SweepRunReport runSweepJobs(const std::vector<SweepJob>& jobs, const SweepRunOptions& options);

}  // namespace cosim
