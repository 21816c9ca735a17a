#pragma once
// What `cosim compare-real` writes into its output folder, each file atomically:
//   compare.json  the figures (real_rmse_m, sim_rmse_m, ratio = real / sim, alignment,
//                 time_offset_s, start_offset_m and mean_offset_m [x, y, z], rmse_by_alignment,
//                 axis_lag_s, amplitude_ratio, warnings, max errors, samples, the window) and
//                 what was fitted;
//   compare.md    the same as a short table, with how the log was placed;
//   compare.png / compare.svg  the figure (experiments/compare/compare_figure.h).
#include <filesystem>
#include <string>

#include "experiments/compare/flight_comparison.h"

namespace cosim {

struct CompareInputs {
  std::filesystem::path run_dir;
  const RunFlight* run = nullptr;
  const FlightLog* log = nullptr;
};

std::string compareJson(const CompareInputs& in, const FlightComparison& c);
std::string compareMarkdown(const CompareInputs& in, const FlightComparison& c);

// Writes compare.json, compare.md and the figure into `dir`; returns the files' names.
std::vector<std::string> writeCompareReport(const std::filesystem::path& dir,
                                            const CompareInputs& in, const FlightComparison& c);

}  // namespace cosim
