#pragma once
// A chart that compares runs: one metric of a results table (a sweep's results.csv, a
// reproduction's CSV) against one column, one series per group, drawn by gnuplot as PNG and SVG.
#include <filesystem>
#include <string>

namespace cosim {

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
