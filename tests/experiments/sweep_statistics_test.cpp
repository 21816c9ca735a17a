// Summary statistics of a sweep: the numbers (mean, sd, median, bootstrap 95 % interval) and the
// grouping (seeds pooled, ok jobs only for metrics, ok_rate over all).
#include <gtest/gtest.h>

#include <cmath>

#include "experiments/sweep/descriptive_statistics.h"
#include "experiments/sweep/sweep_summary.h"

namespace cosim {
namespace {

TEST(SweepStatistics, DescribesASampleWithABootstrapInterval) {
  const Descriptive d = describeSample({2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_EQ(d.n, 8u);
  EXPECT_DOUBLE_EQ(d.mean, 5.0);
  EXPECT_NEAR(d.sd, std::sqrt(32.0 / 7.0), 1e-12);  // sample sd: squares sum to 32, n - 1 = 7
  EXPECT_DOUBLE_EQ(d.median, 4.5);
  // The bootstrap means are multiples of 1/8, skewed right by the 9; 200 000 resamples (in
  // Python) put their 2.5 % and 97.5 % points at 3.75 and 6.5. Student's t gave 5 -+ 1.79.
  EXPECT_NEAR(d.ci95_low, 3.75, 0.2);
  EXPECT_NEAR(d.ci95_high, 6.5, 0.2);
  EXPECT_EQ(describeSample({2, 4, 4, 4, 5, 5, 7, 9}).ci95_low, d.ci95_low);  // fixed seed
}

TEST(SweepStatistics, IntervalsStayInsideTheSampleRange) {
  // Two positive lengths: Student's t interval was [-1.7, 23.7] m; the bootstrap's means are
  // 10, 11 and 12 (probabilities 1/4, 1/2, 1/4), so its 2.5 % and 97.5 % points are the values.
  const Descriptive lengths = describeSample({10, 12});
  EXPECT_DOUBLE_EQ(lengths.ci95_low, 10.0);
  EXPECT_DOUBLE_EQ(lengths.ci95_high, 12.0);
  // A success rate of 2 in 3 stays within [0, 1].
  const Descriptive rate = describeSample({1, 1, 0});
  EXPECT_GE(rate.ci95_low, 0.0);
  EXPECT_LE(rate.ci95_high, 1.0);
  EXPECT_LT(rate.ci95_low, rate.mean);
}

TEST(SweepStatistics, OneValueHasNoSpreadAndNoInterval) {
  const Descriptive d = describeSample({3.5});
  EXPECT_DOUBLE_EQ(d.mean, 3.5);
  EXPECT_DOUBLE_EQ(d.median, 3.5);
  EXPECT_TRUE(std::isnan(d.sd));
  EXPECT_TRUE(std::isnan(d.ci95_low));
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
  EXPECT_NE(csv.find("w.yaml,astar,planned_length_m,3,2,11,1.41421,11,10,12"),
            std::string::npos)
      << csv;
}

TEST(SweepStatistics, AMetricNoOkJobHasGetsNoRow) {
  SweepTable t;
  t.header = {"job", "scenario", "planner.name", "status", "planned_length_m"};
  t.first_metric_column = 4;
  t.rows = {{"0", "w.yaml", "astar", "ok", "10"},
            {"1", "w.yaml", "rrt", "failed", "0"},
            {"2", "w.yaml", "rrt", "timeout", ""}};
  const SweepSummary s = summarizeSweep(t);
  // astar: ok_rate and its length; rrt: ok_rate 0 only (was a planned_length_m row with n = 0).
  ASSERT_EQ(s.rows.size(), 3u);
  EXPECT_EQ(s.rows[2].group, (std::vector<std::string>{"w.yaml", "rrt"}));
  EXPECT_EQ(s.rows[2].metric, "ok_rate");
  EXPECT_DOUBLE_EQ(s.rows[2].stats.mean, 0.0);
  for (const auto& r : s.rows) EXPECT_GT(r.stats.n, 0u) << r.metric;
}

TEST(SweepStatistics, SeedKeysAreThoseEndingInSeed) {
  EXPECT_TRUE(isSeedKey("sim.seed"));
  EXPECT_TRUE(isSeedKey("planner.seed"));
  EXPECT_FALSE(isSeedKey("planner.name"));
  EXPECT_FALSE(isSeedKey("seeds.count"));
}

}  // namespace
}  // namespace cosim
