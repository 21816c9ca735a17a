// The sweep runner against a stand-in job program (a shell script that behaves as the job's
// planner.name tells it): every way a job can end is recorded, the sweep goes on, finished jobs
// are not run again, an interrupt leaves running jobs unfinished, and the merge orders rows by id.
#include "experiments/sweep/sweep_runner.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/output_manifest.h"
#include "experiments/sweep/job_result.h"
#include "experiments/sweep/sweep_results_table.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

namespace fs = std::filesystem;

// Called as: program run SCENARIO --out DIR --quiet --no-video --no-images --set
// planner.name=B --set sim.seed=S
const char* kFakeCosim = R"(#!/bin/sh
out=$4
behaviour=${9#planner.name=}
seed=${11#sim.seed=}
echo "$behaviour $seed" >> "$(dirname "$0")/calls.txt"
case $behaviour in
  ok) printf '{\n  "reached_goal": true,\n  "status": 0,\n  "length_m": %s.5,\n  "counters": {"expansions": 7}\n}\n' "$seed" > "$out/metrics.json"; exit 0 ;;
  fail) printf '{"reached_goal": false, "length_m": null}\n' > "$out/metrics.json"; exit 1 ;;
  bad) exit 2 ;;
  internal) exit 3 ;;
  crash) kill -SEGV $$ ;;
  hang) exec sleep 30 ;;
  stubborn) trap '' TERM; sleep 30; exit 0 ;;
esac
)";

class SweepRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = cosim::test::makeFreshDir("sweep-runner");
    std::ofstream(root_ / "fake-cosim") << kFakeCosim;
    fs::permissions(root_ / "fake-cosim", fs::perms::owner_all);
    std::ofstream(root_ / "world.yaml") << "# any text: the fake program does not read it\n";
  }
  void TearDown() override { fs::remove_all(root_); }

  std::vector<SweepJob> jobs(const std::string& behaviours, const std::string& seeds = "[1]") {
    spec_ = parseSweepSpec("scenarios: [world.yaml]\nvary:\n  planner.name: " + behaviours +
                               "\n  sim.seed: " + seeds + "\n",
                           root_ / "sweep.yaml");
    return expandSweepJobs(spec_, root_ / "out");
  }
  SweepRunOptions options(int parallel) {
    SweepRunOptions o;
    o.out_dir = root_ / "out";
    o.jobs = parallel;
    o.program = (root_ / "fake-cosim").string();
    o.job_timeout_s = 0.5;
    o.kill_grace_s = 0.3;
    o.progress = false;
    return o;
  }
  std::string status(const SweepJob& job, std::size_t count) {
    const auto r = readJobResult(sweepJobDir(root_ / "out", job, count));
    return r ? jobStatusName(r->status) : "unfinished";
  }
  // What a real `cosim run` does as it ends: record the files it wrote in its folder
  // (core/output_manifest.h), so that a later attempt of the job may replace them. The fake
  // program writes none, so the jobs' files are recorded here.
  void recordJobFiles() {
    for (const auto& e : fs::recursive_directory_iterator(root_ / "out" / "jobs"))
      if (e.is_regular_file()) recordWrittenOutput(e.path());
  }
  int calls() {
    std::ifstream in(root_ / "calls.txt");
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  }
  fs::path root_;
  SweepSpec spec_;
};

TEST_F(SweepRunnerTest, EveryWayAJobEndsIsRecordedAndTheSweepGoesOn) {
  const auto js = jobs("[ok, fail, bad, internal, crash, hang, stubborn]");
  const SweepRunReport r = runSweepJobs(js, options(3));
  EXPECT_EQ(r.ran, 7u);
  EXPECT_EQ(status(js[0], 7), "ok");
  EXPECT_EQ(status(js[1], 7), "failed");
  EXPECT_EQ(status(js[2], 7), "bad_input");
  EXPECT_EQ(status(js[3], 7), "crashed");  // exit 3: internal error
  EXPECT_EQ(status(js[4], 7), "crashed");  // SIGSEGV
  EXPECT_EQ(status(js[5], 7), "timeout");  // SIGTERM after 0.5 s
  EXPECT_EQ(status(js[6], 7), "timeout");  // ignores SIGTERM: SIGKILL 0.3 s later
  EXPECT_EQ(readJobResult(sweepJobDir(root_ / "out", js[4], 7))->signal, 11);
  EXPECT_EQ(r.statuses.at("crashed"), 2u);
}

TEST_F(SweepRunnerTest, ASecondRunSkipsFinishedJobs) {
  const auto js = jobs("[ok, fail]", "[1, 2, 3]");
  EXPECT_EQ(runSweepJobs(js, options(2)).ran, 6u);
  const SweepRunReport again = runSweepJobs(js, options(2));
  EXPECT_EQ(again.ran, 0u);
  EXPECT_EQ(again.already_finished, 6u);
  EXPECT_EQ(calls(), 6);
}

TEST_F(SweepRunnerTest, ShardsRunDisjointSlicesThatTogetherCoverTheSweep) {
  const auto js = jobs("[ok]", "[1, 2, 3, 4, 5]");
  SweepRunOptions o = options(1);
  o.shard = {2, 2};
  EXPECT_EQ(runSweepJobs(js, o).ran, 2u);  // ids 1 and 3
  EXPECT_EQ(status(js[0], 5), "unfinished");
  EXPECT_EQ(status(js[1], 5), "ok");
  o.shard = {1, 2};
  EXPECT_EQ(runSweepJobs(js, o).ran, 3u);
  EXPECT_EQ(calls(), 5);
}

TEST_F(SweepRunnerTest, AnInterruptLeavesRunningJobsUnfinishedAndKeepsFinishedOnes) {
  const auto js = jobs("[ok, hang, hang, ok]");
  SweepRunOptions o = options(2);  // ok and hang start; ok ends and the second hang takes its place
  o.job_timeout_s = 60;
  std::atomic<bool> interrupt{false};
  o.interrupt = &interrupt;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(800));
    interrupt = true;
  });
  const SweepRunReport r = runSweepJobs(js, o);
  stopper.join();
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(status(js[0], 4), "ok");
  EXPECT_EQ(status(js[1], 4), "unfinished");
  EXPECT_EQ(status(js[2], 4), "unfinished");
  EXPECT_EQ(status(js[3], 4), "unfinished");  // never started
  EXPECT_EQ(r.unfinished, 3u);
  // The merge lists the finished job only, complete.
  const SweepTable t = mergeSweepResults(spec_, js, root_ / "out");
  EXPECT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.unfinished, 3u);
}

TEST_F(SweepRunnerTest, TheMergeHasOneRowPerJobByIdWithFlattenedMetrics) {
  const auto js = jobs("[ok, fail, crash]", "[1, 2]");
  runSweepJobs(js, options(3));
  const SweepTable t = mergeSweepResults(spec_, js, root_ / "out");
  EXPECT_EQ(sweepTableCsv(t).substr(0, sweepTableCsv(t).find('\n')),
            "job,scenario,planner.name,sim.seed,status,reached_goal,length_m,counters.expansions,"
            "job_wall_time_s");
  ASSERT_EQ(t.rows.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(t.rows[i][0], std::to_string(i));
  EXPECT_EQ(t.rows[1][4], "ok");
  EXPECT_EQ(t.rows[1][6], "2.5");  // seed 2
  EXPECT_EQ(t.rows[1][7], "7");
  EXPECT_EQ(t.rows[2][4], "failed");
  EXPECT_EQ(t.rows[2][6], "");  // null
  EXPECT_EQ(t.rows[5][4], "crashed");
  EXPECT_EQ(t.rows[5][5], "");  // no metrics.json
}

TEST_F(SweepRunnerTest, AResultMadeForAnotherVersionOfTheJobDoesNotCount) {
  auto js = jobs("[ok]");
  runSweepJobs(js, options(1));
  recordJobFiles();
  js[0].fingerprint = "0000000000000000";  // as if the scenario file had changed
  EXPECT_EQ(runSweepJobs(js, options(1)).ran, 1u);
  EXPECT_EQ(calls(), 2);
}

TEST_F(SweepRunnerTest, AMergeOfResultsFromTwoBuildsOfTheProgramSaysSo) {
  const auto js = jobs("[ok]", "[1, 2]");
  runSweepJobs(js, options(1));
  EXPECT_EQ(mergeSweepResults(spec_, js, root_ / "out").program_builds, 1u);
  // A rebuild (a new modification time), then job 1 runs again.
  fs::last_write_time(root_ / "fake-cosim",
                      fs::last_write_time(root_ / "fake-cosim") + std::chrono::seconds(10));
  fs::remove(sweepJobDir(root_ / "out", js[1], 2) / "result.json");
  recordJobFiles();
  runSweepJobs(js, options(1));
  EXPECT_EQ(mergeSweepResults(spec_, js, root_ / "out").program_builds, 2u);
}

}  // namespace
}  // namespace cosim
