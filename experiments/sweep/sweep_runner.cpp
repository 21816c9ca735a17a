#include "experiments/sweep/sweep_runner.h"

#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "core/output_manifest.h"
#include "experiments/sweep/child_process.h"
#include "experiments/sweep/job_result.h"

namespace cosim {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct RunningJob {
  const SweepJob* job = nullptr;
  std::filesystem::path dir;
  ChildProcess child;
  Clock::time_point started;
  bool timed_out = false;  // the runner sent SIGTERM for the time limit
  bool stopped = false;    // the runner sent SIGTERM because the sweep was interrupted
  Clock::time_point signalled;
  bool killed = false;
};

std::string duration(double s) {
  char buf[32];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  else
    std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600,
                  static_cast<int>(s) / 60 % 60);
  return buf;
}

std::string describe(const SweepJob& job) {
  std::string s = job.scenario;
  for (std::size_t k = 0; k < job.values.size(); ++k) s += (k ? ", " : " ") + job.values[k];
  return s;
}

RunningJob startJob(const SweepJob& job, const SweepRunOptions& o, std::size_t job_count) {
  RunningJob r;
  r.job = &job;
  r.dir = sweepJobDir(o.out_dir, job, job_count);
  // A job folder left by an interrupted or outdated attempt must not lend its files to this one;
  // it goes only if everything in it is proven cosim's (core/output_manifest.h: the job's run
  // records its files, the sweep its log.txt and result.json).
  requireCosimOutput(r.dir, "--out");
  std::error_code ec;
  std::filesystem::remove_all(r.dir, ec);
  std::filesystem::create_directories(r.dir, ec);
  if (ec) throw std::runtime_error("cannot create " + r.dir.string() + ": " + ec.message());
  r.child =
      ChildProcess::start(o.program, sweepJobArguments(job, r.dir, o.video), r.dir / "log.txt");
  r.started = Clock::now();
  return r;
}

// What the progress lines need: the tag, the start and every finished job's status, an earlier
// invocation's included (the line counts "done" over both, and so must its "(40 ok)").
struct SweepProgress {
  const SweepRunOptions& o;
  std::string tag;
  Clock::time_point t0;
  std::size_t job_count;
  std::map<std::string, std::size_t> finished_statuses;
};

// The line after each finished job: done over the shard, by status, the rate and the ETA; a job
// that neither succeeded nor failed is named with its log.
void reportFinished(const SweepProgress& p, const SweepRunReport& report, const RunningJob& r,
                    JobStatus status) {
  const std::string& tag = p.tag;
  if (status != JobStatus::Ok && status != JobStatus::Failed)
    std::cerr << tag << ": job " << sweepJobDirName(r.job->id, p.job_count) << " ("
              << describe(*r.job) << ") " << jobStatusName(status)
              << "; log: " << (r.dir / "log.txt").string() << "\n";
  const std::size_t done = report.already_finished + report.ran;
  const double elapsed = secondsSince(p.t0);
  const double per_job = elapsed / static_cast<double>(report.ran);
  const std::size_t left = report.in_shard - done;
  std::string counts;
  for (const auto& [name, n] : p.finished_statuses)
    counts += (counts.empty() ? "" : ", ") + std::to_string(n) + " " + name;
  char rate[64];
  std::snprintf(rate, sizeof rate, "%.1f jobs/min", 60.0 / per_job);
  std::cerr << tag << ": " << done << "/" << report.in_shard << " done (" << counts << "), " << rate
            << ", ETA " << duration(per_job * static_cast<double>(left)) << "\n";
}

// A job whose process has ended: its result.json, unless the runner stopped it before it could
// finish (then a later invocation runs it again).
void finishJob(const RunningJob& r, int wait_status, const std::string& build,
               SweepProgress& progress, SweepRunReport& report) {
  recordWrittenOutput(r.dir / "log.txt");  // the job's output, written by this process
  const bool exited_by_itself =
      !r.stopped || (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0);
  if (r.stopped && !exited_by_itself) {
    ++report.unfinished;  // no result.json: a later invocation runs it again
    return;
  }
  JobResult res;
  res.job = r.job->id;
  res.fingerprint = r.job->fingerprint;
  res.scenario = r.job->scenario;
  res.status = classifyJobExit(wait_status, r.timed_out);
  res.exit_code = wait_status != -1 && WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
  res.signal = wait_status != -1 && WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : 0;
  res.wall_time_s = secondsSince(r.started);
  res.program_build = build;
  writeJobResult(r.dir, res);
  ++report.ran;
  ++report.statuses[jobStatusName(res.status)];
  ++progress.finished_statuses[jobStatusName(res.status)];
  if (progress.o.progress) reportFinished(progress, report, r, res.status);
}

// A job still running: SIGTERM past the time limit, SIGKILL past the grace period after that
// (a job that ignores SIGTERM).
void watchJob(RunningJob& r, const SweepRunOptions& o) {
  const double age = secondsSince(r.started);
  if (!r.timed_out && !r.stopped && age > o.job_timeout_s) {
    r.timed_out = true;
    r.signalled = Clock::now();
    r.child.signal(SIGTERM);
  }
  if ((r.timed_out || r.stopped) && !r.killed && secondsSince(r.signalled) > o.kill_grace_s) {
    r.killed = true;
    r.child.signal(SIGKILL);
  }
}

// The jobs of the shard not finished by an earlier invocation; counts the shard and the finished
// ones into `report` and `finished_statuses`.
std::vector<const SweepJob*> pendingJobs(const std::vector<SweepJob>& jobs,
                                         const SweepRunOptions& o, SweepRunReport& report,
                                         std::map<std::string, std::size_t>& finished_statuses) {
  std::vector<const SweepJob*> pending;
  for (const auto& job : jobs) {
    if (!o.shard.owns(job.id)) continue;
    ++report.in_shard;
    if (sweepJobFinished(sweepJobDir(o.out_dir, job, jobs.size()), job)) {
      ++report.already_finished;
      ++finished_statuses[jobStatusName(
          readJobResult(sweepJobDir(o.out_dir, job, jobs.size()))->status)];
    } else
      pending.push_back(&job);
  }
  return pending;
}

}  // namespace

std::vector<std::string> sweepJobArguments(const SweepJob& job, const std::filesystem::path& dir,
                                           bool video) {
  std::vector<std::string> args = {"run", std::filesystem::absolute(job.scenario_path).string(),
                                   "--out", dir.string(), "--quiet"};
  // Without video a sweep renders nothing at all: pictures of every job cost more CPU than short
  // flights do.
  if (!video) {
    args.push_back("--no-video");
    args.push_back("--no-images");
  }
  for (const auto& ov : job.overrides) {
    args.push_back("--set");
    args.push_back(ov);
  }
  return args;
}

std::filesystem::path sweepJobDir(const std::filesystem::path& out_dir, const SweepJob& job,
                                  std::size_t job_count) {
  return out_dir / "jobs" / sweepJobDirName(job.id, job_count);
}

bool sweepJobFinished(const std::filesystem::path& job_dir, const SweepJob& job) {
  const auto r = readJobResult(job_dir);
  return r && r->fingerprint == job.fingerprint && r->job == job.id;
}

SweepRunReport runSweepJobs(const std::vector<SweepJob>& jobs, const SweepRunOptions& o) {
  SweepRunReport report;
  SweepProgress progress{o, "", Clock::now(), jobs.size(), {}};
  const std::vector<const SweepJob*> pending =
      pendingJobs(jobs, o, report, progress.finished_statuses);
  // The folders of the jobs to run again go as each starts: refused now, before any job runs, if
  // one holds a file cosim cannot prove it wrote (core/output_manifest.h).
  for (const SweepJob* job : pending)
    requireCosimOutput(sweepJobDir(o.out_dir, *job, jobs.size()), "--out");
  progress.tag = o.shard.whole() ? std::string("sweep")
                                 : "sweep [shard " + std::to_string(o.shard.index) + "/" +
                                       std::to_string(o.shard.count) + "]";
  const std::string& tag = progress.tag;
  const int parallel = std::max(1, o.jobs);
  if (o.progress)
    std::cerr << tag << ": " << report.in_shard << " jobs, " << report.already_finished
              << " already finished, " << pending.size() << " to run, " << parallel
              << " at a time\n";

  const std::string build = programBuildIdentity(o.program);
  std::vector<RunningJob> running;
  std::size_t next = 0;
  bool stopping = false;
  const auto interrupted = [&] { return o.interrupt && o.interrupt->load(); };
  while (next < pending.size() || !running.empty()) {
    if (!stopping && interrupted()) {
      stopping = true;
      report.interrupted = true;
      if (o.progress)
        std::cerr << tag << ": interrupted; stopping " << running.size() << " running job(s)\n";
      for (auto& r : running) {
        r.stopped = true;
        r.signalled = Clock::now();
        r.child.signal(SIGTERM);
      }
    }
    if (stopping && next < pending.size()) {
      report.unfinished += pending.size() - next;
      next = pending.size();
    }
    while (!stopping && static_cast<int>(running.size()) < parallel && next < pending.size())
      running.push_back(startJob(*pending[next++], o, jobs.size()));

    bool reaped = false;
    for (std::size_t i = 0; i < running.size();) {
      RunningJob& r = running[i];
      int wait_status = 0;
      if (r.child.finished(wait_status)) {
        reaped = true;
        finishJob(r, wait_status, build, progress, report);
        running.erase(running.begin() + static_cast<long>(i));
        continue;
      }
      watchJob(r, o);
      ++i;
    }
    // A freed slot is filled at once; otherwise poll. Every millisecond a slot stands idle costs
    // short jobs throughput (a 0.2 s job loses 2.5 % to a 5 ms gap).
    if (!reaped && (!running.empty() || next < pending.size()))
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  report.wall_time_s = secondsSince(progress.t0);
  if (o.progress && !report.interrupted)
    std::cerr << tag << ": finished " << report.ran << " job(s) in " << duration(report.wall_time_s)
              << "\n";
  return report;
}

}  // namespace cosim
