#include "render/figures.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/temporary_name.h"
#include "render/csv_table.h"
#include "render/figure_data.h"
#include "render/gnuplot.h"
#include "render/log_lookup.h"
#include "render/overlay_palette.h"
#include "sim/flight_metrics.h"

namespace cosim {

namespace {

// A scratch folder beside the outputs; the finished files are renamed out of it, so every
// figure appears complete or not at all.
class WorkDir {
 public:
  explicit WorkDir(const std::filesystem::path& parent) {
    std::filesystem::create_directories(parent);
    // A new folder of this process's own: nothing already at the name is followed or removed.
    path_ = createTemporaryFolder(parent / "plot", ".part");
  }
  ~WorkDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  void publish(const std::string& name, const std::filesystem::path& target) const {
    moveIntoPlace(path_ / name, target);
  }

 private:
  std::filesystem::path path_;
};

// Viridis for the error palette, as in the videos.
std::string errorPalette(double scale, const std::string& label) {
  std::ostringstream s;
  s << "set palette defined (";
  for (int i = 0; i <= 8; ++i)
    s << (i ? ", " : "") << i / 8.0 << " '" << hexColour(errorColour(i / 8.0)) << "'";
  s << ")\nset cbrange [0:" << gnuplotNumber(scale) << "]\nset cblabel " << gnuplotString(label)
    << "\n";
  return s.str();
}

// Obstacles as gnuplot objects seen along an axis: `horizontal`/`vertical` are the world axes
// (0 x, 1 y, 2 z) on the figure's x and y. shown: which obstacles to draw (all if empty). From
// above, an obstacle's shade says its height (taller is darker), so a path over a low block
// does not look like a collision.
std::string obstacleObjects(const World& world, int horizontal, int vertical,
                            const std::vector<bool>& shown = {}) {
  std::ostringstream s;
  int id = 1;
  const double world_height = std::max(1e-9, world.bounds_max.z() - world.bounds_min.z());
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    if (!shown.empty() && !shown[i]) continue;
    const Obstacle& o = world.obstacles[i];
    const double top = o.pos.z() + 0.5 * (o.type == ObstacleType::Box        ? o.size.z()
                                          : o.type == ObstacleType::Cylinder ? o.height
                                                                             : 2.0 * o.radius);
    const double opacity =
        vertical == 2
            ? 0.55
            : 0.2 + 0.65 * std::clamp((top - world.bounds_min.z()) / world_height, 0.0, 1.0);
    const std::string style = " fc rgb '" + std::string(kObstacleFill) +
                              "' fillstyle transparent solid " + gnuplotNumber(opacity) +
                              " border lc rgb '" + kObstacleEdge + "' lw 0.8 back\n";
    const double c = std::cos(o.yaw_deg * M_PI / 180.0), sn = std::sin(o.yaw_deg * M_PI / 180.0);
    if (o.type == ObstacleType::Sphere || (o.type == ObstacleType::Cylinder && vertical != 2)) {
      // A circle from above (spheres, and cylinders standing on z).
      s << "set object " << id++ << " ellipse at " << gnuplotNumber(o.pos[horizontal]) << ","
        << gnuplotNumber(o.pos[vertical]) << " size " << gnuplotNumber(2 * o.radius) << ","
        << gnuplotNumber(2 * o.radius) << " units xy" << style;
    } else if (o.type == ObstacleType::Cylinder || vertical == 2) {
      // From the side: the horizontal extent of the (rotated) footprint, the full height.
      double half_h;
      if (o.type == ObstacleType::Cylinder) {
        half_h = o.radius;
      } else {
        half_h = horizontal == 0 ? 0.5 * (std::abs(c) * o.size.x() + std::abs(sn) * o.size.y())
                                 : 0.5 * (std::abs(sn) * o.size.x() + std::abs(c) * o.size.y());
      }
      const double half_v = 0.5 * (o.type == ObstacleType::Cylinder ? o.height : o.size.z());
      s << "set object " << id++ << " rectangle from " << gnuplotNumber(o.pos[horizontal] - half_h)
        << "," << gnuplotNumber(o.pos[2] - half_v) << " to "
        << gnuplotNumber(o.pos[horizontal] + half_h) << "," << gnuplotNumber(o.pos[2] + half_v)
        << style;
    } else {
      // A box from above: its rotated footprint.
      s << "set object " << id++ << " polygon";
      const double hx = 0.5 * o.size.x(), hy = 0.5 * o.size.y();
      const double corners[5][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}, {-hx, -hy}};
      for (int k = 0; k < 5; ++k) {
        const double x = o.pos.x() + c * corners[k][0] - sn * corners[k][1];
        const double y = o.pos.y() + sn * corners[k][0] + c * corners[k][1];
        s << (k ? " to " : " from ") << gnuplotNumber(x) << "," << gnuplotNumber(y);
      }
      s << style;
    }
  }
  return s.str();
}

// The side view shows only the obstacles whose footprint comes within this distance (m) of a
// vehicle's flown or planned path: projected onto one plane, every obstacle of the world would
// seem to stand in the path's way.
constexpr double kSideViewDepth = 1.0;

std::vector<bool> obstaclesNearPaths(const World& world, const RunLog& log) {
  std::vector<bool> near(world.obstacles.size(), false);
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    const Obstacle& o = world.obstacles[i];
    // A point's horizontal distance to the footprint: the point taken to the obstacle's centre
    // height.
    const auto close = [&](Eigen::Vector3d p) {
      p.z() = o.pos.z();
      return o.signedDistance(p) < kSideViewDepth;
    };
    for (const VehicleLog& v : log.vehicles) {
      for (const auto& p : v.planned_path) near[i] = near[i] || close(p);
      const std::size_t step = std::max<std::size_t>(1, v.samples.size() / kMaxPlotRowsPerVehicle);
      for (std::size_t k = 0; k < v.samples.size() && !near[i]; k += step)
        near[i] = close(v.samples[k].pos);
    }
  }
  return near;
}

std::string axisName(int axis) {
  return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

// How the figures draw a run, decided once for all three.
struct FigureStyle {
  bool several = false;   // a team: one colour per vehicle
  bool by_error = false;  // the flown paths coloured by tracking error (the palette)
  bool plans = false;     // planned paths and references drawn
  FigureFiles files;
};

// The paths over the obstacles along two world axes (top: x,y; side: x or y, z), lowest first:
// planned paths (a thin line, small open circles at the corners, so the flown line on top shows
// through), references (dashed), flown paths, goals (open squares), starts (small dots inside
// them where a start is another's goal). Five plot elements whatever the team's size: each
// vehicle's colour comes from the files' rgb column.
std::string pathPlot(int h, int v, const FigureStyle& f) {
  std::vector<std::string> items;
  const std::string hc = std::to_string(h + 2), vc = std::to_string(v + 2);
  const std::string rh = std::to_string(h + 5), rv = std::to_string(v + 5);
  const std::string ph = std::to_string(h + 1), pv = std::to_string(v + 1);
  const auto title = [&](const std::string& one, const std::string& team) {
    return " title " + gnuplotString(f.several ? team : one);
  };
  if (f.plans && f.files.any_plan)
    items.push_back("'plans.dat' using " + ph + ":" + pv +
                    ":4 with linespoints lw 1.2 pt 6 ps 0.45 lc rgb variable" +
                    title("planned path", "planned paths (one colour each)"));
  if (f.plans && f.files.any_reference)
    items.push_back("'refs.dat' using " + rh + ":" + rv + " with lines lw 1.2 dt (6,4) lc rgb '" +
                    hexColour(kReferenceColour) + "'" +
                    title("reference trajectory", "reference trajectories"));
  if (f.files.any_flown) {
    if (f.by_error)
      items.push_back(
          "'flown.dat' using " + hc + ":" + vc + ":8 with lines lw " + (f.several ? "1.6" : "2.6") +
          " lc palette" +
          title("flown (colour: tracking error)", "flown paths (colour: tracking error)"));
    else
      items.push_back("'flown.dat' using " + hc + ":" + vc +
                      ":9 with lines lw 1.6 lc rgb variable" +
                      title("flown", "flown paths (one colour each)"));
  }
  items.push_back("'goals.dat' using " + ph + ":" + pv +
                  ":4 with points pt 4 ps 1.5 lw 1.5 lc rgb variable" + title("goal", "goals"));
  items.push_back("'starts.dat' using " + ph + ":" + pv + ":4 with points pt 7 ps " +
                  (f.several ? "0.6" : "1.0") + " lc rgb variable" + title("start", "starts"));
  std::string p = "plot ";
  for (std::size_t i = 0; i < items.size(); ++i) p += (i ? ", \\\n     " : "") + items[i];
  return p;
}

// The data's extent: flown and planned paths, starts and goals (a figure's axes fit it, not the
// whole world: a Crazyflie's 1 m figure-eight in a 6 m room filled a third of its axes).
struct Extent {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL),
                  hi = Eigen::Vector3d::Constant(-HUGE_VAL);
  void add(const Eigen::Vector3d& p) {
    if (!p.allFinite()) return;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
};

Extent dataExtent(const RunLog& log, const World& world) {
  Extent e;
  for (const VehicleLog& v : log.vehicles) {
    for (std::size_t i : evenSampleIndices(v.samples.size(), kMinPlotRowsPerVehicle))
      e.add(v.samples[i].pos);
    for (const auto& p : v.planned_path) e.add(p);
    e.add(v.goal);
  }
  if (!(e.lo.x() <= e.hi.x())) return {world.bounds_min, world.bounds_max};
  // A margin of a tenth of the span (at least 0.2 m), inside the world where the data is.
  const Eigen::Vector3d pad = (0.1 * (e.hi - e.lo)).cwiseMax(0.2);
  Extent fitted;
  fitted.lo = (e.lo - pad).cwiseMax(world.bounds_min).cwiseMin(e.lo);
  fitted.hi = (e.hi + pad).cwiseMin(world.bounds_max).cwiseMax(e.hi);
  return fitted;
}

// The error figure: each vehicle's tracking error over the flight, the time axis ending where
// the data does. Up to eight vehicles each have a key entry with its RMSE and max, a dashed RMSE
// line and its arrival mark; a larger team one key entry (the worst vehicle named).
std::string errorPlot(const RunRecord& record, const FigureStyle& f) {
  const RunLog& log = record.log;
  std::ostringstream s;
  const bool named = log.vehicles.size() <= 8;
  std::size_t worst = 0;
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    const VehicleLog& v = log.vehicles[a];
    const FlightMetrics& m = record.metrics.vehicles[a];
    if (m.rmse_m > record.metrics.vehicles[worst].rmse_m) worst = a;
    if (!named) continue;
    const std::string colour = hexColour(f.several ? vehicleColour(a) : kFlownPathColour);
    s << "set arrow from graph 0, first " << gnuplotNumber(m.rmse_m) << " to graph 1, first "
      << gnuplotNumber(m.rmse_m) << " nohead dt (4,4) lw 1 lc rgb '" << colour << "'\n";
    if (v.reached_goal && v.arrival_time >= 0)
      s << "set arrow from first " << gnuplotNumber(v.arrival_time) << ", graph 0 to first "
        << gnuplotNumber(v.arrival_time) << ", graph 1 nohead dt (2,3) lw 1 lc rgb '#606060'\n"
        << "set label " << gnuplotString("goal reached ") << " at first "
        << gnuplotNumber(v.arrival_time)
        << ", graph 0.5 right rotate by 90 offset -0.8,0 tc rgb '#404040' font ',9'\n";
    s << "set label " << gnuplotString("RMSE") << " at graph 0.005, first "
      << gnuplotNumber(m.rmse_m) << " left offset 0,0.6 tc rgb '" << colour << "' font ',9'\n";
  }
  const auto round_mm = [](double x) { return gnuplotNumber(std::round(x * 1000) / 1000); };
  std::string plot = "plot ";
  if (named) {
    // One element per vehicle (its key entry): every index'th block of flown.dat.
    for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
      if (log.vehicles[a].samples.empty()) continue;
      const FlightMetrics& m = record.metrics.vehicles[a];
      const std::string colour = hexColour(f.several ? vehicleColour(a) : kFlownPathColour);
      plot += std::string(plot.size() > 5 ? ", \\\n     " : "") +
              "'flown.dat' every :::" + std::to_string(a) + "::" + std::to_string(a) +
              " using 1:8 with lines lw 2 lc rgb '" + colour + "' title " +
              gnuplotString((f.several ? log.vehicles[a].name + ": " : std::string()) + "RMSE " +
                            round_mm(m.rmse_m) + " m, max " + round_mm(m.max_error_m) + " m");
    }
  } else if (!log.vehicles.empty()) {
    const FlightMetrics& m = record.metrics.vehicles[worst];
    plot += "'flown.dat' using 1:8:9 with lines lw 1 lc rgb variable title " +
            gnuplotString(std::to_string(log.vehicles.size()) +
                          " vehicles, one colour each; worst RMSE " + log.vehicles[worst].name +
                          " " + round_mm(m.rmse_m) + " m");
  }
  if (plot.size() <= 5) plot += "0 notitle";  // nothing flown: an empty frame
  s << "set xrange [0:" << gnuplotNumber(std::max(f.files.duration, 1e-3)) << "]\n" << plot << "\n";
  return s.str();
}

// What the colour bar measures against: the reference every vehicle shares, or each one's own.
std::string referenceName(const std::vector<ErrorReference>& refs) {
  bool one_reference = true;
  for (ErrorReference r : refs) one_reference = one_reference && r == refs.front();
  return !one_reference ? "each vehicle's own reference"
         : refs.empty() ? "the planned path"
                        : std::string("the ") + errorReferenceName(refs.front());
}

// The look every figure shares: border, grid, tics and key.
const char* kCommonStyle =
    "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid lc rgb '#dddddd' lw 1\n"
    "set tics out nomirror\nset key box lc rgb '#bbbbbb' opaque samplen 2.5 spacing 1.1 "
    "font ',10' Left reverse\n";

// The top view's script: equal axes over the data's extent.
std::string topView(const World& world, const Extent& fit, const std::string& what,
                    const std::string& palette, const FigureStyle& f) {
  std::ostringstream top;
  top << kCommonStyle << (f.by_error ? palette : "unset colorbox\n") << obstacleObjects(world, 0, 1)
      << "set title "
      << gnuplotString(std::string(f.plans ? "Top view: planned vs flown path ("
                                           : "Top view: flown paths (") +
                       what + "; darker obstacles are taller)")
      << "\n"
      << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\n"
      << "set xrange [" << gnuplotNumber(fit.lo.x()) << ":" << gnuplotNumber(fit.hi.x())
      << "]\nset yrange [" << gnuplotNumber(fit.lo.y()) << ":" << gnuplotNumber(fit.hi.y())
      << "]\nset key outside below horizontal center\n"
      << pathPlot(0, 1, f) << "\n";
  return top.str();
}

// The side view's script, along the axis the flight crosses most (the other horizontal axis is
// depth).
std::string sideView(const RunLog& log, const World& world, const Extent& fit,
                     const std::string& palette, const FigureStyle& f) {
  const Eigen::Vector3d lo = world.bounds_min, hi = world.bounds_max;
  int along = 0;
  if (!log.vehicles.empty() && !log.vehicles[0].samples.empty()) {
    const Eigen::Vector3d d = log.vehicles[0].goal - log.vehicles[0].samples.front().pos;
    along = std::abs(d.y()) > std::abs(d.x()) ? 1 : 0;
  }
  std::ostringstream side;
  side << kCommonStyle << (f.by_error ? palette : "unset colorbox\n")
       << obstacleObjects(world, along, 2, obstaclesNearPaths(world, log)) << "set title "
       << gnuplotString("Side view (looking along " + axisName(1 - along) + "; obstacles within " +
                        gnuplotNumber(kSideViewDepth) + " m of the paths only; height exaggerated)")
       << "\n"
       << "set xlabel '" << axisName(along) << " [m]'\nset ylabel 'z [m]'\nset size ratio 0.42\n"
       << "set xrange [" << gnuplotNumber(fit.lo[along]) << ":" << gnuplotNumber(fit.hi[along])
       << "]\nset yrange [" << gnuplotNumber(lo.z()) << ":" << gnuplotNumber(hi.z())
       << "]\nset key outside below horizontal center\n"
       << pathPlot(along, 2, f) << "\n";
  return side.str();
}

// The largest tracking error of any vehicle (the colour scale's top).
double largestError(const RunRecord& record) {
  double max_error = 0.0;
  for (const std::vector<double>& err : record.metrics.tracking_errors)
    for (double e : err) max_error = std::max(max_error, e);
  return max_error;
}

}  // namespace

std::vector<std::string> writeRunFigures(const Scenario& scenario, const RunRecord& record,
                                         const std::filesystem::path& dir) {
  WorkDir work(dir);
  const RunLog& log = record.log;
  const World& world = scenario.world;
  // Each vehicle's error against its own reference, as in its metrics (the record's).
  std::vector<ErrorReference> refs;
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) refs.push_back(record.errorReferenceOf(a));
  FigureStyle f;
  f.several = log.vehicles.size() > 1;
  f.by_error = !f.several || scenario.render.team_error;
  f.plans = !f.several || scenario.render.team_plans;
  f.files = writeFigureFiles(record, work.path());
  const double scale =
      errorScaleMax(largestError(record), errorScaleFloor(scenario.sim.goal_tolerance));
  const Extent fit = dataExtent(log, world);
  const std::string& planner_name = record.setup.primarySections().planner.name;
  const std::string what =
      pathSourceName(scenario, planner_name) + ", " + vehicleControllers(record);
  const std::string reference_name = referenceName(refs);
  const std::string palette = errorPalette(scale, "error to " + reference_name + " [m]");

  std::ostringstream error;
  error << kCommonStyle << "set title "
        << gnuplotString("Tracking error against " + reference_name + " (" + what + ")")
        << "\nset xlabel 'time [s]'\nset ylabel 'position error [m]'\nset yrange [0:*]\n"
        << "set key top right\n"
        << errorPlot(record, f);

  // The top view keeps equal axes: the canvas height follows the data's aspect ratio (the
  // plot is ~760 px wide; title, axes and key take ~190 px).
  const double aspect = (fit.hi.y() - fit.lo.y()) / std::max(1e-9, fit.hi.x() - fit.lo.x());
  const int top_height = 2 * static_cast<int>(std::clamp(95.0 + 380.0 * aspect, 250.0, 700.0));
  std::string script = plotBoth("error", 1000, 480, error.str()) + "reset\n" +
                       plotBoth("top", 1000, top_height, topView(world, fit, what, palette, f)) +
                       "reset\n" +
                       plotBoth("side", 1000, 560, sideView(log, world, fit, palette, f));
  runGnuplot(script, work.path());
  const std::vector<std::string> names = {"error", "top", "side"};
  for (const auto& n : names)
    for (const char* ext : {".png", ".svg"}) work.publish(n + ext, dir / (n + ext));
  return names;
}

}  // namespace cosim
