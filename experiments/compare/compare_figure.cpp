#include "experiments/compare/compare_figure.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

namespace {

constexpr std::size_t kMaxPlotRows = 2500;  // per series: smooth at print size, small SVGs

std::string plotValue(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// t ref_x ref_y sim_x sim_y real_x real_y real_error sim_error, decimated evenly, always
// ending with the last sample.
std::string dataRows(const FlightComparison& c) {
  std::ostringstream s;
  const std::size_t n = c.t.size(), step = std::max<std::size_t>(1, n / kMaxPlotRows);
  for (std::size_t k = 0; k < n; k = (k + 1 < n && k + step >= n) ? n - 1 : k + step) {
    s << plotValue(c.t[k]) << ' ' << plotValue(c.reference[k].x()) << ' '
      << plotValue(c.reference[k].y()) << ' ' << plotValue(c.sim[k].x()) << ' '
      << plotValue(c.sim[k].y()) << ' ' << plotValue(c.real[k].x()) << ' '
      << plotValue(c.real[k].y()) << ' ' << plotValue(c.real_error[k]) << ' '
      << plotValue(c.sim_error[k]) << '\n';
  }
  return s.str();
}

std::string figureBody(const FlightComparison& c) {
  const std::string real = hexColour(vehicleColour(0)), sim = hexColour(vehicleColour(1));
  const std::string ref = hexColour(kReferenceColour);
  std::ostringstream b;
  b << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid lc rgb '#dddddd'\n"
    << "set tics out nomirror\nset key top right box lc rgb '#bbbbbb' font ',10'\n"
    << "set autoscale\nset multiplot layout 1,2\n"
    << "set title 'paths from above (real in the run frame)'\n"
    << "set xlabel 'x (m)'\nset ylabel 'y (m)'\nset size ratio -1\n"
    << "plot 'compare.dat' using 2:3 with lines lw 1.2 dt (6,4) lc rgb '" << ref
    << "' title 'reference', \\\n"
    << "     'compare.dat' using 4:5 with lines lw 3.5 lc rgb '" << sim
    << "' title 'simulated', \\\n"
    << "     'compare.dat' using 6:7 with lines lw 2 lc rgb '" << real << "' title 'real'\n"
    << "set size noratio\nset title 'position error against the reference'\n"
    << "set xlabel 'run time (s)'\nset ylabel 'error (m)'\nset yrange [0:*]\n"
    << "plot 'compare.dat' using 1:9 with lines lw 3.5 lc rgb '" << sim << "' title "
    << gnuplotString("simulated, RMSE " + plotValue(c.sim_rmse_m) + " m") << ", \\\n"
    << "     'compare.dat' using 1:8 with lines lw 2 lc rgb '" << real << "' title "
    << gnuplotString("real, RMSE " + plotValue(c.real_rmse_m) + " m") << "\n"
    << "unset multiplot\n";
  return b.str();
}

}  // namespace

void writeCompareFigure(const FlightComparison& c, const std::filesystem::path& out_base) {
  const GnuplotScratch scratch(out_base, "compare");
  scratch.write("compare.dat", dataRows(c));
  runGnuplot(plotBoth("compare", 1400, 600, figureBody(c)), scratch.dir());
  scratch.publish("compare");
}

}  // namespace cosim
