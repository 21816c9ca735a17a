#include "render/success_rate_chart.h"

#include <sstream>

#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

void writeSuccessRateChart(const std::vector<SuccessRateSeries>& series, const std::string& title,
                           const std::filesystem::path& out_base) {
  const GnuplotScratch scratch(out_base, "success");

  std::ostringstream data, body;
  for (const auto& s : series) {
    for (const auto& [agents, rate] : s.points) data << agents << ' ' << rate << '\n';
    data << "\n\n";  // next gnuplot index
  }
  scratch.write("success.dat", data.str());
  body << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid lc rgb '#dddddd'\n"
       << "set tics out nomirror\nset key bottom left box lc rgb '#bbbbbb' font ',10'\n"
       << "set title " << gnuplotString(title) << "\nset xlabel 'agents'\n"
       << "set ylabel 'success rate (%)'\nset yrange [-3:103]\nset ytics 0,20,100\nplot ";
  for (std::size_t g = 0; g < series.size(); ++g)
    body << (g ? ", \\\n     " : "") << "'success.dat' index " << g
         << " using 1:2 with linespoints lw 2 dt " << g + 1 << " pt " << 4 + 2 * g
         << " ps 0.9 lc rgb '" << hexColour(vehicleColour(g + 4)) << "' title "
         << gnuplotString(series[g].name);
  body << "\n";
  runGnuplot(plotBoth("success", 900, 500, body.str()), scratch.dir());
  scratch.publish("success");
}

}  // namespace cosim
