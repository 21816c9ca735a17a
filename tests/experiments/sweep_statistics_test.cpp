// Summary statistics of a sweep: the numbers (mean, sd, median, Student-t 95 % interval) and the
// grouping (seeds pooled, ok jobs only for metrics, ok_rate over all).
#include <gtest/gtest.h>

#include <cmath>

#include "experiments/sweep/descriptive_statistics.h"
#include "experiments/sweep/sweep_summary.h"

namespace cosim {
namespace {

TEST(SweepStatistics, DescribesASampleWithAStudentTInterval) {
  const Descriptive d = describeSample({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(d.n, 8u);
  EXPECT_DOUBLE_EQ(d.mean, 5.0);
  EXPECT_NEAR(d.sd, std::sqrt(32.0 / 7.0), 1e-12);  // sample sd: squares sum to 32, n - 1 = 7
  EXPECT_DOUBLE_EQ(d.median, 4.5);
  // t(0.975, 7) = 2.36462
  EXPECT_NEAR(d.ci95_high - d.mean, 2.36462 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-9);
  EXPECT_NEAR(d.mean - d.ci95_low, d.ci95_high - d.mean, 1e-12);
}

TEST(SweepStatistics, OneValueHasNoSpreadAndNoInterval) {
  const Descriptive d = describeSample({3.5});
  EXPECT_DOUBLE_EQ(d.mean, 3.5);
  EXPECT_DOUBLE_EQ(d.median, 3.5);
  EXPECT_TRUE(std::isnan(d.sd));
  EXPECT_TRUE(std::isnan(d.ci95_low));
}

TEST(SweepStatistics, StudentQuantilesMatchTables) {
  EXPECT_NEAR(studentT975(1), 12.7062, 1e-4);
  EXPECT_NEAR(studentT975(9), 2.26216, 1e-5);
  EXPECT_NEAR(studentT975(40), 2.02108, 2e-4);  // beyond the table: Cornish-Fisher
  EXPECT_NEAR(studentT975(120), 1.97993, 2e-4);
}

TEST(SweepStatistics, GroupsPoolSeedsAndMetricsUseOkJobsOnly) {
  SweepTable t;
  t.header = {"job",    "scenario",         "planner.name", "sim.seed",
              "status", "planned_length_m", "planner"};
  t.first_metric_column = 5;
  t.rows = {{"0", "w.yaml", "astar", "1", "ok", "10", "astar"},
            {"1", "w.yaml", "astar", "2", "ok", "12", "astar"},
            {"2", "w.yaml", "astar", "3", "failed", "0", "astar"},
            {"3", "w.yaml", "rrt", "1", "ok", "20", "rrt"},
            {"4", "w.yaml", "rrt", "2", "crashed", "", ""}};
  const SweepSummary s = summarizeSweep(t);
  EXPECT_EQ(s.group_columns, (std::vector<std::string>{"scenario", "planner.name"}));
  // Two groups x (ok_rate, planned_length_m); the text column `planner` is not a metric.
  ASSERT_EQ(s.rows.size(), 4u);
  EXPECT_EQ(s.rows[0].metric, "ok_rate");
  EXPECT_EQ(s.rows[0].jobs, 3u);
  EXPECT_NEAR(s.rows[0].stats.mean, 2.0 / 3.0, 1e-12);
  EXPECT_EQ(s.rows[1].metric, "planned_length_m");
  EXPECT_EQ(s.rows[1].stats.n, 2u);  // the failed run's 0 m is left out
  EXPECT_DOUBLE_EQ(s.rows[1].stats.mean, 11.0);
  EXPECT_EQ(s.rows[3].group, (std::vector<std::string>{"w.yaml", "rrt"}));
  EXPECT_DOUBLE_EQ(s.rows[3].stats.mean, 20.0);
  const std::string csv = sweepSummaryCsv(s);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "scenario,planner.name,metric,jobs,n,mean,sd,median,ci95_low,ci95_high");
  EXPECT_NE(csv.find("w.yaml,astar,planned_length_m,3,2,11,1.41421,11,-1.7062,23.7062"),
            std::string::npos)
      << csv;
}

TEST(SweepStatistics, SeedKeysAreThoseEndingInSeed) {
  EXPECT_TRUE(isSeedKey("sim.seed"));
  EXPECT_TRUE(isSeedKey("planner.seed"));
  EXPECT_FALSE(isSeedKey("planner.name"));
  EXPECT_FALSE(isSeedKey("seeds.count"));
}

}  // namespace
}  // namespace cosim
