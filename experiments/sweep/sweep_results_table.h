#pragma once
// The merged results: one row per finished job, ordered by job id (never by completion order, so
// the table is the same whatever --jobs or sharding ran it). Columns: job, scenario, one per
// varied key, status, then every metric of the job's metrics.json (nested objects flattened with
// dots, e.g. planner_counters.expansions; the single-vehicle `vehicles` list is skipped because
// it repeats the top-level metrics; metrics named like a fixed column, e.g. its numeric `status`,
// are left out), and last the job's wall-clock time as the runner measured it.
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweep/sweep_jobs.h"

namespace cosim {

struct SweepTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // same length as header; "" = no value
  std::size_t first_metric_column = 0;         // metrics run from here up to the last column
  std::size_t unfinished = 0;                  // jobs without a (matching) result.json
  std::size_t program_builds = 0;              // distinct builds of cosim that ran the rows
};

SweepTable mergeSweepResults(const SweepSpec& spec, const std::vector<SweepJob>& jobs,
                             const std::filesystem::path& out_dir);

// RFC 4180 CSV (fields quoted when needed), header first.
std::string sweepTableCsv(const SweepTable& table);

}  // namespace cosim
