#include "render/comparison_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "render/csv_table.h"
#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

namespace {

// The chart's values per (group, x); groups and x values in order of first appearance (x
// sorted by value when every x is a number).
struct ChartCells {
  std::vector<std::string> groups, xs;
  std::map<std::pair<std::string, std::string>, std::vector<double>> cells;
  bool numeric_x = true;
};

ChartCells readChartCells(const std::filesystem::path& csv_path, const std::string& x_column,
                          const std::string& y_column, const std::string& group_column) {
  ChartCells c;
  std::vector<std::string>& groups = c.groups;
  std::vector<std::string>& xs = c.xs;
  auto& cells = c.cells;
  bool& numeric_x = c.numeric_x;
  const CsvTable t = readCsvTable(csv_path);
  const std::string file = csv_path.string();
  const std::size_t xi = t.column(x_column, file), yi = t.column(y_column, file);
  const std::size_t gi = group_column.empty() ? 0 : t.column(group_column, file);
  for (const auto& row : t.rows) {
    char* end = nullptr;
    const double y = std::strtod(row[yi].c_str(), &end);
    if (row[yi].empty() || *end != '\0' || !std::isfinite(y)) continue;
    const std::string g = group_column.empty() ? y_column : row[gi];
    const std::string& x = row[xi];
    char* xend = nullptr;
    std::strtod(x.c_str(), &xend);
    numeric_x = numeric_x && !x.empty() && *xend == '\0';
    if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
    if (std::find(xs.begin(), xs.end(), x) == xs.end()) xs.push_back(x);
    cells[{g, x}].push_back(y);
  }
  if (cells.empty())
    throw InputError(file, "column " + y_column, "no row has a numeric value to chart");
  if (numeric_x)
    std::stable_sort(xs.begin(), xs.end(), [](const std::string& a, const std::string& b) {
      return std::strtod(a.c_str(), nullptr) < std::strtod(b.c_str(), nullptr);
    });
  return c;
}

// The mean and the sample standard deviation (0 for one value).
std::pair<double, double> meanAndDeviation(const std::vector<double>& v) {
  double mean = 0.0, var = 0.0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (double x : v) var += (x - mean) * (x - mean);
  return std::make_pair(mean,
                        v.size() > 1 ? std::sqrt(var / static_cast<double>(v.size() - 1)) : 0.0);
}

// Numeric x: one line with error bars per group (one gnuplot index each).
void lineChart(const ChartCells& c, std::ostringstream& data, std::ostringstream& body) {
  const auto& groups = c.groups;
  const auto& xs = c.xs;
  const auto& cells = c.cells;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (const auto& x : xs) {
      auto it = cells.find({groups[g], x});
      if (it == cells.end()) continue;
      const auto [mean, sd] = meanAndDeviation(it->second);
      data << x << ' ' << gnuplotNumber(mean) << ' ' << gnuplotNumber(sd) << '\n';
    }
    data << "\n\n";  // next gnuplot index
  }
  body << "plot ";
  for (std::size_t g = 0; g < groups.size(); ++g)
    body << (g ? ", \\\n     " : "") << "'chart.dat' index " << g
         << " using 1:2:3 with yerrorlines lw 2 pt 7 ps 0.8 lc rgb '"
         << hexColour(vehicleColour(g + 4)) << "' title " << gnuplotString(groups[g]);
  body << "\n";
}

// Any other x: clustered bars with error bars, x values in order of first appearance.
void barChart(const ChartCells& c, std::ostringstream& data, std::ostringstream& body) {
  const auto& groups = c.groups;
  const auto& xs = c.xs;
  const auto& cells = c.cells;
  for (const auto& x : xs) {
    std::string label = x;
    std::replace(label.begin(), label.end(), ' ', '_');
    data << '"' << label << '"';
    for (const auto& g : groups) {
      auto it = cells.find({g, x});
      if (it == cells.end()) {
        data << " ? ?";
      } else {
        const auto [mean, sd] = meanAndDeviation(it->second);
        data << ' ' << gnuplotNumber(mean) << ' ' << gnuplotNumber(sd);
      }
    }
    data << '\n';
  }
  body << "set style data histogram\nset style histogram errorbars gap 1.5 lw 1\n"
       << "set style fill solid 0.85 border rgb '#303030'\nset boxwidth 0.9\nset yrange [0:*]\n"
       << "set xtics rotate by -30 left noenhanced\n";
  if (groups.size() == 1) body << "set key off\n";
  body << "plot ";
  for (std::size_t g = 0; g < groups.size(); ++g)
    body << (g ? ", \\\n     " : "") << "'chart.dat' using " << 2 + 2 * g << ":" << 3 + 2 * g
         << (g == 0 ? ":xtic(1)" : "") << " lc rgb '" << hexColour(vehicleColour(g + 4))
         << "' title " << gnuplotString(groups[g]);
  body << "\n";
}

}  // namespace

void writeComparisonChart(const std::filesystem::path& csv_path, const std::string& x_column,
                          const std::string& y_column, const std::string& group_column,
                          const std::filesystem::path& out_base) {
  const ChartCells c = readChartCells(csv_path, x_column, y_column, group_column);
  GnuplotScratch scratch(out_base, "plot");
  std::ostringstream data, body;
  body << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid ytics lc rgb '#dddddd'\n"
       << "set tics out nomirror\nset key outside right top box lc rgb '#bbbbbb' font ',10'\n"
       << "set datafile missing '?'\nset title " << gnuplotString(y_column + " by " + x_column)
       << "\n"
       << "set xlabel " << gnuplotString(x_column) << "\nset ylabel " << gnuplotString(y_column)
       << "\n";
  // Colours: the agents' palette, distinguishable for colour-blind readers.
  if (c.numeric_x)
    lineChart(c, data, body);
  else
    barChart(c, data, body);
  scratch.write("chart.dat", data.str());
  runGnuplot(plotBoth("chart", 900, 500, body.str()), scratch.dir());
  scratch.publish("chart");
}

}  // namespace cosim
