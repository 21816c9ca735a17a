#include "experiments/bench/sweep_throughput.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "experiments/sweep/child_process.h"
#include "experiments/sweep/sweep_runner.h"

namespace cosim::bench {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// One by one, each job a `cosim run` with the arguments the sweep runner gives it (same work),
// started the moment the previous one ends.
double runOneByOne(const std::vector<SweepJob>& jobs, const fs::path& dir) {
  const auto t0 = Clock::now();
  for (const auto& job : jobs) {
    const fs::path out = dir / std::to_string(job.id);
    fs::create_directories(out);
    ChildProcess child =
        ChildProcess::start("/proc/self/exe", sweepJobArguments(job, out, false), out / "log.txt");
    child.wait();  // as a shell loop would: no polling delay on this side
  }
  return secondsSince(t0);
}

double cpuSeconds(int who) {
  rusage u{};
  ::getrusage(who, &u);
  return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// Wall time of the sweep; `runner_cpu_share` gets the runner's own CPU time (scheduling loop,
// result files) over its jobs' CPU time, a measure of overhead that other load does not skew.
double runSweep(const std::vector<SweepJob>& jobs, const fs::path& dir, int parallel,
                double* runner_cpu_share = nullptr) {
  SweepRunOptions o;
  o.out_dir = dir;
  o.jobs = parallel;
  o.progress = false;
  const double self0 = cpuSeconds(RUSAGE_SELF), children0 = cpuSeconds(RUSAGE_CHILDREN);
  const auto t0 = Clock::now();
  runSweepJobs(jobs, o);
  const double wall = secondsSince(t0);
  if (runner_cpu_share)
    *runner_cpu_share =
        (cpuSeconds(RUSAGE_SELF) - self0) / std::max(1e-9, cpuSeconds(RUSAGE_CHILDREN) - children0);
  return wall;
}

}  // namespace

Section benchSweepThroughput(bool quick) {
  const fs::path root =
      fs::temp_directory_path() / ("cosim-bench-sweep-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  // Short flights (~10 s simulated, well under a second of CPU each) in a small city: the runner's
  // fixed costs weigh most on short jobs.
  const int seeds = quick ? 2 : 6;
  std::string seed_list;
  for (int s = 1; s <= seeds; ++s) seed_list += (s > 1 ? ", " : "") + std::to_string(s);
  const SweepSpec spec = parseSweepSpec(
      "generators: [{type: city, density: 0.5, size: [24, 24, 6], seed: 1}]\n"
      "vary:\n  planner.name: [astar, theta_star]\n  sim.seed: [" +
          seed_list + "]\n",
      root / "bench.yaml");
  const std::vector<SweepJob> jobs = expandSweepJobs(spec, root);

  // Interleaved rounds, best of each: the machine is shared and its load drifts.
  const int rounds = quick ? 1 : 2;
  double one_by_one = 1e300, sweep1 = 1e300, sweep2 = 1e300, cpu_share = 0;
  double load[1] = {0};
  ::getloadavg(load, 1);
  for (int r = 0; r < rounds; ++r) {
    const fs::path d = root / ("round" + std::to_string(r));
    one_by_one = std::min(one_by_one, runOneByOne(jobs, d / "one_by_one"));
    sweep1 = std::min(sweep1, runSweep(jobs, d / "jobs1", 1));
    sweep2 = std::min(sweep2, runSweep(jobs, d / "jobs2", 2, &cpu_share));
  }
  fs::remove_all(root);

  const double n = static_cast<double>(jobs.size());
  const double overhead = sweep1 / one_by_one - 1.0, speedup = one_by_one / sweep2;
  Section out;
  out.name = "sweep_throughput";
  out.figures = {{"one_by_one_jobs_per_min", 60.0 * n / one_by_one, "1/min"},
                 {"sweep_jobs1_jobs_per_min", 60.0 * n / sweep1, "1/min"},
                 {"sweep_jobs2_jobs_per_min", 60.0 * n / sweep2, "1/min"},
                 {"runner_overhead", 100.0 * overhead, "%"},
                 {"runner_cpu_share", 100.0 * cpu_share, "%"},
                 {"speedup_jobs2", speedup, "x"},
                 {"mean_job_s", one_by_one / n, "s"}};
  out.note = std::to_string(jobs.size()) +
             " short flights (city 24x24 m, astar/theta_star); targets: overhead < 5 % " +
             (overhead < 0.05 ? "met" : "NOT met") + ", speed-up on 2 jobs >= 1.8x " +
             (speedup >= 1.8 ? "met" : "NOT met") + " (" +
             std::to_string(std::thread::hardware_concurrency()) + " cores, load average " +
             std::to_string(load[0]).substr(0, 4) +
             " at the start: other load lowers the speed-up)";
  return out;
}

}  // namespace cosim::bench
