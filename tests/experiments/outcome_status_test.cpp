// How a sweep job and a MAPF benchmark run ended, as enums written by name: a sweep job's
// result.json holds the status's name and reads back as the same status (a name no runner writes
// makes the job unfinished, to be run again); a skipped MAPF run is "skipped" in benchmark.csv
// with no time or memory figures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "experiments/mapf/mapf_benchmark_report.h"
#include "experiments/sweep/job_result.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

namespace fs = std::filesystem;

TEST(SweepJobStatus, ResultJsonHoldsTheNameAndReadsBackAsTheStatus) {
  const fs::path dir = test::freshDir("job-status");
  fs::create_directories(dir);
  JobResult r;
  r.job = 4;
  r.fingerprint = "abc";
  r.scenario = "s.yaml";
  r.status = JobStatus::BadInput;
  r.exit_code = 2;
  writeJobResult(dir, r);
  EXPECT_NE(test::slurp(dir / "result.json").find("\"status\": \"bad_input\""), std::string::npos);
  const auto back = readJobResult(dir);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->status, JobStatus::BadInput);
  EXPECT_EQ(back->exit_code, 2);
  fs::remove_all(dir);
}

TEST(SweepJobStatus, AStatusNoRunnerWritesLeavesTheJobUnfinished) {
  const fs::path dir = test::freshDir("job-status-unknown");
  fs::create_directories(dir);
  std::ofstream(dir / "result.json")
      << "{\"job\": 1, \"fingerprint\": \"f\", \"scenario\": \"s.yaml\", \"status\": \"done\", "
         "\"exit_code\": 0, \"signal\": 0, \"wall_time_s\": 1.0}\n";
  EXPECT_FALSE(readJobResult(dir).has_value());
  for (const JobStatus s : {JobStatus::Ok, JobStatus::Failed, JobStatus::Timeout,
                            JobStatus::Crashed, JobStatus::BadInput})
    EXPECT_EQ(jobStatusNamed(jobStatusName(s)), s) << jobStatusName(s);
  fs::remove_all(dir);
}

TEST(MapfRunStatus, ASkippedRunIsWrittenSkippedWithoutFigures) {
  MapfBenchmarkRow skipped;
  skipped.scen = "empty-8-8-random-1.scen";
  skipped.planner = "cbs";
  skipped.agents = 6;
  skipped.status = MapfRunStatus::Skipped;
  skipped.time_ms = 12.5;  // not run: no time is reported even if one was set
  skipped.message = "not run: failed at 4 agents";
  MapfBenchmarkRow solved = skipped;
  solved.status = MapfRunStatus::Solved;
  solved.success = true;
  solved.sum_of_costs = 30;
  solved.makespan = 9;
  const std::string csv = mapfBenchmarkCsv("maps/empty-8-8.map", {skipped, solved});
  EXPECT_NE(csv.find("\nempty-8-8,empty-8-8-random-1,cbs,6,skipped,0,,,,,,,,,,not run: failed at 4 "
                     "agents\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nempty-8-8,empty-8-8-random-1,cbs,6,solved,1,30,9,12.500,12.500,"),
            std::string::npos)
      << csv;
  const MapfBenchmarkTally tally = tallyMapfBenchmark({skipped, solved});
  EXPECT_EQ(tally.at({"cbs", 6}), std::make_pair(2, 1));
}

}  // namespace
}  // namespace cosim
