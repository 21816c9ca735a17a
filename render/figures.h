#pragma once
// Figures for papers, as PNG and SVG, drawn by gnuplot from generated scripts (render/gnuplot.h).
#include <filesystem>
#include <string>
#include <vector>

#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim {

// A run's figures in `dir` (created if needed), each as <name>.png and <name>.svg:
//   error: tracking error over time per vehicle, with its RMSE and the arrival time;
//   top:   planned path, reference and flown path (coloured by tracking error) over the
//          obstacles seen from above, equal axes;
//   side:  the same seen from the side, along the horizontal axis the flight mostly crosses.
// Returns the names written ("error", "top", "side"). Throws std::runtime_error if gnuplot fails.
std::vector<std::string> writeRunFigures(const RunLog& log, const Scenario& scenario,
                                         const std::filesystem::path& dir);

// A comparison chart from a CSV with a header row: y_column against x_column, one series per
// value of group_column (empty: one series). Rows with the same x and group (e.g. seeds) are
// averaged, with error bars of one standard deviation; rows whose y is empty or not a number
// are left out. Numeric x: a line chart; otherwise: clustered bars in order of first
// appearance. Writes out_base.png and out_base.svg (atomically). Throws InputError for a
// missing file or column, or when no row has a numeric y.
void writeComparisonChart(const std::filesystem::path& csv_path, const std::string& x_column,
                          const std::string& y_column, const std::string& group_column,
                          const std::filesystem::path& out_base);

}  // namespace cosim
