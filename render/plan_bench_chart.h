#pragma once
// The figure of `cosim plan-bench`: three panels one above the other, a column per planner in each:
// planning time of every run (box plot, log scale), path length of the solved runs (box plot)
// and success rate (bars, 0 to 100 %). Boxes span the quartiles with the median line and
// whiskers to the furthest value within 1.5 interquartile ranges (Tukey); outliers as points.
// PNG and SVG, by gnuplot.
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

struct PlannerBenchSamples {
  std::string name;
  int runs = 0, solved = 0;
  std::vector<double> times_ms;   // every run
  std::vector<double> lengths_m;  // solved runs
};

// Writes out_base.png and out_base.svg, each complete or not at all. Throws std::runtime_error
// if gnuplot fails.
void writePlanBenchChart(const std::vector<PlannerBenchSamples>& planners, const std::string& title,
                         const std::filesystem::path& out_base);

}  // namespace cosim
