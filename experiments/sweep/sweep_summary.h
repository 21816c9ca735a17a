#pragma once
// Summary statistics of a merged sweep, per group of jobs that differ only in their seeds: the
// group is the scenario plus every varied key except seeds (keys whose last part ends in "seed",
// e.g. sim.seed). For each group: `ok_rate` (status ok as 1, anything else as 0, over all its
// finished jobs), then every numeric metric over the group's ok jobs (a failed run's lengths and
// times would mix two populations; a metric none of them has gets no row). Long format, one row
// per group and metric.
#include <string>
#include <vector>

#include "experiments/sweep/descriptive_statistics.h"
#include "experiments/sweep/sweep_results_table.h"

namespace cosim {

struct SummaryRow {
  std::vector<std::string> group;  // values of SweepSummary::group_columns
  std::string metric;
  std::size_t jobs = 0;  // finished jobs in the group
  Descriptive stats;
};

struct SweepSummary {
  std::vector<std::string> group_columns;  // "scenario" and the non-seed varied keys
  std::vector<SummaryRow> rows;            // groups in order of first job, metrics in column order
};

SweepSummary summarizeSweep(const SweepTable& table);
// A seed key: its last part ends in "seed" (sim.seed, planner.seed).
bool isSeedKey(const std::string& key);
// Header: group columns, metric, jobs, n, mean, sd, median, ci95_low, ci95_high.
std::string sweepSummaryCsv(const SweepSummary& summary);

}  // namespace cosim
