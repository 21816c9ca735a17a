#include "experiments/sweep/sweep_outputs.h"

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "experiments/sweep/sweep_identity.h"
#include "experiments/sweep/sweep_results_table.h"
#include "experiments/sweep/sweep_summary.h"
#include "render/comparison_chart.h"

namespace cosim {

SweepOutputs writeSweepOutputs(const SweepSpec& spec, const std::vector<SweepJob>& jobs,
                               const std::filesystem::path& out_dir) {
  const SweepTable table = mergeSweepResults(spec, jobs, out_dir);
  const SweepSummary summary = summarizeSweep(table);
  SweepOutputs o;
  o.rows = table.rows.size();
  o.unfinished = table.unfinished;
  o.program_builds = table.program_builds;
  o.state = sweepState(jobs.size() - table.unfinished, jobs.size());
  if (table.unfinished > 0) {
    // Nothing half-done under the names of a finished sweep: the tables of the jobs that have
    // results go under .partial names, the complete ones (of an earlier merge) go, and no figure.
    removeStaleResults(out_dir, {"results.csv", "summary.csv", "figure.png", "figure.svg"});
    writeFileAtomically(out_dir / "results.partial.csv", sweepTableCsv(table));
    writeFileAtomically(out_dir / "summary.partial.csv", sweepSummaryCsv(summary));
    writeSweepState(spec, out_dir, jobs.size() - table.unfinished, jobs.size());
    o.figure_problem = "the sweep is " + o.state;
    return o;
  }
  removeStaleResults(out_dir, {"results.partial.csv", "summary.partial.csv"});
  writeFileAtomically(out_dir / "results.csv", sweepTableCsv(table));
  writeFileAtomically(out_dir / "summary.csv", sweepSummaryCsv(summary));
  writeSweepState(spec, out_dir, jobs.size(), jobs.size());
  // The figure: the metric per scenario, one bar per value of output.figure_by, else of the first
  // varied key that is not a seed (seeds are what the bars average over).
  std::string series = spec.figure_by;
  for (const auto& v : spec.vary)
    if (series.empty() && !isSeedKey(v.key)) series = v.key;
  try {
    writeComparisonChart(out_dir / "results.csv", "scenario", spec.figure_metric, series,
                         out_dir / "figure");
  } catch (const std::exception& e) {
    o.figure_problem = e.what();  // the figure is a convenience; the tables are the results
  }
  return o;
}

}  // namespace cosim
