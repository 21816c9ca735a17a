#include "experiments/reproduce/reproduction_map.h"

#include <sstream>

#include "render/gnuplot.h"

namespace cosim::reproduce {

namespace {

// Runs of blocked cells along x in each row; `blocked(x, y)` says which.
template <typename Blocked>
std::vector<Eigen::Vector4d> rowRuns(int nx, int ny, Blocked blocked) {
  std::vector<Eigen::Vector4d> runs;
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx;) {
      if (!blocked(x, y)) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < nx && blocked(x, y)) ++x;
      runs.emplace_back(x0, y, x, y + 1);
    }
  return runs;
}

std::string blockData(const std::vector<Eigen::Vector4d>& blocks) {
  std::ostringstream d;
  for (const auto& b : blocks)
    d << 0.5 * (b[0] + b[2]) << ' ' << 0.5 * (b[1] + b[3]) << ' ' << b[0] << ' ' << b[2] << ' '
      << b[1] << ' ' << b[3] << '\n';
  return d.str();
}

// Colour-blind-safe colours (Okabe and Ito) and dash types, so that overlapping paths stay
// distinguishable in grey print too.
const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                          "#E69F00", "#56B4E9", "#000000", "#F0E442"};

}  // namespace

ReproductionMap gridMap(const std::string& title, const OccupancyGrid& grid, const Cell& start,
                        const Cell& goal) {
  ReproductionMap m;
  m.title = title;
  m.hi = Eigen::Vector2d(grid.nx(), grid.ny());
  if (grid.nz() == 1) {
    m.blocks = rowRuns(grid.nx(), grid.ny(), [&](int x, int y) { return grid.blocked(x, y, 0); });
  } else {
    // The top of a column: one above its highest blocked cell (0: free at every height).
    const auto top = [&](int x, int y) {
      for (int z = grid.nz() - 1; z >= 0; --z)
        if (grid.blocked(x, y, z)) return z + 1;
      return 0;
    };
    for (int h = 1; h <= grid.nz(); ++h)
      for (const auto& r :
           rowRuns(grid.nx(), grid.ny(), [&](int x, int y) { return top(x, y) == h; }))
        m.height_blocks.push_back({r, static_cast<double>(h)});
    m.height_max = grid.nz();
  }
  m.start = Eigen::Vector2d(start.x + 0.5, start.y + 0.5);
  m.goal = Eigen::Vector2d(goal.x + 0.5, goal.y + 0.5);
  return m;
}

std::vector<Eigen::Vector2d> cellCentres(const std::vector<Cell>& cells) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(cells.size());
  for (const Cell& c : cells) points.emplace_back(c.x + 0.5, c.y + 0.5);
  return points;
}

std::string writeReproductionMap(const std::filesystem::path& out_dir, const std::string& name,
                                 int index, const ReproductionMap& map) {
  const std::string base = name + "_map" + std::to_string(index);
  // A reproduction run for its tables alone (no output folder, as tests call it) draws nothing.
  if (out_dir.empty()) return base;
  GnuplotScratch scratch(out_dir / base, base);
  std::ostringstream body;
  body << "set size ratio -1\nset key outside right top box lc rgb '#bbbbbb' font ',10'\n"
       << "set title " << gnuplotString(map.title) << " font ',11'\n"
       << "set xlabel " << gnuplotString(std::string("x [") + map.unit + "]") << "\nset ylabel "
       << gnuplotString(std::string("y [") + map.unit + "]") << "\nset xrange [" << map.lo.x()
       << ":" << map.hi.x() << "]\nset yrange [" << map.lo.y() << ":" << map.hi.y() << "]\n"
       << "set tics out nomirror\n";
  int object = 1;
  for (const auto& poly : map.polygons) {
    body << "set object " << object++ << " polygon from ";
    for (std::size_t i = 0; i <= poly.size(); ++i) {
      const Eigen::Vector2d& p = poly[i % poly.size()];
      body << (i ? " to " : "") << p.x() << "," << p.y();
    }
    body << " fs solid 0.55 noborder fc rgb '#707070' back\n";
  }
  std::vector<std::string> plots;
  if (!map.blocks.empty()) {
    scratch.write("blocks.dat", blockData(map.blocks));
    plots.push_back(
        "'blocks.dat' with boxxyerror fs solid 1.0 noborder lc rgb '#6b6b6b' "
        "title 'obstacle'");
  }
  if (!map.height_blocks.empty()) {
    std::ostringstream d;
    for (const auto& b : map.height_blocks)
      d << 0.5 * (b.rect[0] + b.rect[2]) << ' ' << 0.5 * (b.rect[1] + b.rect[3]) << ' ' << b.rect[0]
        << ' ' << b.rect[2] << ' ' << b.rect[1] << ' ' << b.rect[3] << ' ' << b.top << '\n';
    scratch.write("heights.dat", d.str());
    body << "set palette defined (0 '#e6e6e6', 1 '#3a3a3a')\nset cbrange [0:" << map.height_max
         << "]\nset cblabel " << gnuplotString(std::string("obstacle top [") + map.unit + "]")
         << "\nset colorbox user origin graph 1.04, graph 0 size 0.025, 0.45\n";
    plots.push_back(
        "'heights.dat' using 1:2:3:4:5:6:7 with boxxyerror fs solid 1.0 noborder lc palette "
        "title 'obstacle (shade: its top)'");
  }
  if (!map.polygons.empty())  // a key entry for the polygons drawn as objects
    plots.push_back("NaN with boxes fs solid 0.55 lc rgb '#707070' title 'obstacle'");
  for (std::size_t k = 0; k < map.paths.size(); ++k) {
    if (map.paths[k].points.empty()) continue;  // a method without a path: nothing to draw
    std::ostringstream d;
    for (const auto& p : map.paths[k].points) d << p.x() << ' ' << p.y() << '\n';
    const std::string file = "path" + std::to_string(k) + ".dat";
    scratch.write(file, d.str());
    plots.push_back(gnuplotString(file) + " with lines lw " + (k == 0 ? "2.6" : "1.8") + " dt " +
                    std::to_string(1 + k % 5) + " lc rgb '" + kColours[k % 8] + "' title " +
                    gnuplotString(map.paths[k].label));
  }
  if (!map.moving_obstacle_starts.empty()) {
    std::ostringstream d;
    for (const auto& p : map.moving_obstacle_starts) d << p.x() << ' ' << p.y() << '\n';
    scratch.write("movers.dat", d.str());
    plots.push_back(
        "'movers.dat' with points pt 4 ps 1.4 lc rgb '#000000' "
        "title 'moving obstacle (start)'");
  }
  std::ostringstream ends;
  ends << map.start.x() << ' ' << map.start.y() << '\n';
  for (const auto& p : map.more_starts) ends << p.x() << ' ' << p.y() << '\n';
  ends << "\n\n" << map.goal.x() << ' ' << map.goal.y() << '\n';
  for (const auto& p : map.more_goals) ends << p.x() << ' ' << p.y() << '\n';
  scratch.write("ends.dat", ends.str());
  plots.push_back("'ends.dat' index 0 with points pt 7 ps 1.8 lc rgb '#009E73' title 'start'");
  plots.push_back("'ends.dat' index 1 with points pt 9 ps 2.0 lc rgb '#D55E00' title 'goal'");
  body << "plot ";
  for (std::size_t i = 0; i < plots.size(); ++i) body << (i ? ", \\\n     " : "") << plots[i];
  body << "\n";
  runGnuplot(plotBoth("map", 900, 640, body.str()), scratch.dir());
  scratch.publish("map");
  return base;
}

std::string mapFiguresMarkdown(const std::vector<std::string>& files,
                               const std::vector<std::string>& how) {
  std::string md = "## Rebuilt maps\n\n";
  for (std::size_t i = 0; i < files.size(); ++i)
    md += "- " + files[i] + ".png (and .svg): " + (i < how.size() ? how[i] : std::string()) + "\n";
  md += "\n";
  for (const auto& f : files) md += "![" + f + "](" + f + ".png)\n";
  return md + "\n";
}

}  // namespace cosim::reproduce
