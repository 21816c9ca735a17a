#pragma once
// The merge step: results.csv (one row per finished job, by job id), summary.csv (statistics per
// group), sweep-state.json (experiments/sweep/sweep_identity.h) and figure.png/.svg
// (render/comparison_chart.h: the `output.figure` metric per scenario, one bar per value of
// output.figure_by or the first non-seed varied key, mean with one standard deviation), each
// written atomically into the sweep's folder. While jobs are missing (an interrupted sweep, a merge
// of unfinished shards) the tables are results.partial.csv and summary.partial.csv, with no figure,
// and sweep-state.json says "partial: N of M jobs": nothing half-done carries the names of a
// finished sweep.
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweep/sweep_jobs.h"

namespace cosim {

struct SweepOutputs {
  std::size_t rows = 0;
  std::size_t unfinished = 0;
  std::size_t program_builds = 0;  // > 1: the rows come from different builds of cosim
  std::string figure_problem;      // why figure.png was not drawn ("" if it was)
  std::string state;               // "complete" or "partial: N of M jobs"
};

SweepOutputs writeSweepOutputs(const SweepSpec& spec, const std::vector<SweepJob>& jobs,
                               const std::filesystem::path& out_dir);

}  // namespace cosim
