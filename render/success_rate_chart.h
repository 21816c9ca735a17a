#pragma once
// The MAPF benchmark's figure: success rate (%) against the number of agents, one line per
// planner, the y axis fixed from 0 to 100 % and each line with its own dash and marker, so that
// planners that all solve everything stay visible on top of each other. PNG and SVG, by gnuplot.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cosim {

struct SuccessRateSeries {
  std::string name;
  std::vector<std::pair<int, double>> points;  // (agents, success rate in %), agents ascending
};

// Writes out_base.png and out_base.svg, each complete or not at all. Throws std::runtime_error
// if gnuplot fails.
void writeSuccessRateChart(const std::vector<SuccessRateSeries>& series, const std::string& title,
                           const std::filesystem::path& out_base);

}  // namespace cosim
