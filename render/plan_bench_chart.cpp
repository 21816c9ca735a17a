#include "render/plan_bench_chart.h"

#include <algorithm>
#include <sstream>

#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

namespace {

// One gnuplot data block per planner (blank-line pairs separate `index` blocks).
std::string blocks(const std::vector<std::vector<double>>& values) {
  std::ostringstream out;
  out.precision(10);
  for (const auto& v : values) {
    for (double x : v) out << x << '\n';
    out << "\n\n";
  }
  return out.str();
}

// A box-plot panel of one data file: a box per planner that has values, else an empty panel
// with a note.
std::string boxPanel(const std::vector<std::vector<double>>& values, const std::string& file,
                     const std::string& ylabel, const std::string& empty_note) {
  std::ostringstream s;
  s << "set ylabel " << gnuplotString(ylabel) << "\n";
  std::ostringstream plot;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i].empty()) continue;
    plot << (plot.tellp() > 0 ? ", \\\n     " : "") << "'" << file << "' index " << i << " using ("
         << i + 1 << "):1 with boxplot lc rgb '" << hexColour(vehicleColour(i)) << "' notitle";
  }
  if (plot.tellp() > 0) {
    s << "plot " << plot.str() << "\n";
  } else {
    s << "set label 1 " << gnuplotString(empty_note) << " at graph 0.5, 0.5 center\n"
      << "set yrange [0:1]\nplot -1 notitle\nunset label 1\nset autoscale y\n";
  }
  return s.str();
}

}  // namespace

void writePlanBenchChart(const std::vector<PlannerBenchSamples>& planners, const std::string& title,
                         const std::filesystem::path& out_base) {
  const GnuplotScratch scratch(out_base, "plan-bench");

  std::vector<std::vector<double>> times, lengths;
  std::ostringstream success, xtics;
  for (std::size_t i = 0; i < planners.size(); ++i) {
    const PlannerBenchSamples& p = planners[i];
    std::vector<double> t = p.times_ms;
    for (double& x : t) x = std::max(x, 1e-3);  // log scale: a sub-microsecond run shows at 1 us
    times.push_back(t);
    lengths.push_back(p.lengths_m);
    success << i + 1 << ' ' << (p.runs ? 100.0 * p.solved / p.runs : 0.0) << '\n';
    xtics << (i ? ", " : "") << gnuplotString(p.name) << ' ' << i + 1;
  }
  scratch.write("time.dat", blocks(times));
  scratch.write("length.dat", blocks(lengths));
  scratch.write("success.dat", success.str());

  const std::size_t n = planners.size();
  std::ostringstream body;
  body << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid ytics lc rgb '#dddddd'\n"
       << "set tics out nomirror\nset xtics (" << xtics.str() << ") rotate by -35 font ',9'\n"
       << "set xrange [0.4:" << n + 0.6 << "]\nset style fill solid 0.35 border\n"
       << "set boxwidth 0.55\nset style boxplot outliers pointtype 7\n"
       << "set multiplot layout 3,1 title " << gnuplotString(title) << "\n"
       << "set title 'planning time, every run'\nset logscale y\n"
       << boxPanel(times, "time.dat", "time (ms)", "no runs") << "unset logscale y\n"
       << "set title 'path length, solved runs'\n"
       << boxPanel(lengths, "length.dat", "length (m)", "no solved runs")
       << "set title 'success rate'\nset ylabel 'solved (%)'\nset yrange [0:105]\n"
       << "plot 'success.dat' using 1:2 with boxes lc rgb '#4477aa' notitle\n"
       << "unset multiplot\n";
  const int width = std::max(900, 80 * static_cast<int>(n) + 250);
  runGnuplot(plotBoth("plan_bench", width, 1250, body.str()), scratch.dir());
  scratch.publish("plan_bench");
}

}  // namespace cosim
