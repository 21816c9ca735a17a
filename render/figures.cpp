#include "render/figures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/temporary_name.h"
#include "render/csv_table.h"
#include "render/gnuplot.h"
#include "render/log_lookup.h"
#include "render/overlay_palette.h"
#include "sim/flight_metrics.h"

namespace cosim {

namespace {

constexpr std::size_t kMaxPlotRows = 2500;  // per series: smooth at print size, small SVGs
const char* kObstacleFill = "#9aa3b0";
const char* kObstacleEdge = "#5b6473";

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

void writeText(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

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

// One series file per vehicle: t x y z ref_x ref_y ref_z error (decimated evenly in time).
void writeVehicleData(const VehicleLog& v, const std::vector<double>& err,
                      const std::filesystem::path& file) {
  std::ostringstream s;
  const std::size_t step = std::max<std::size_t>(1, v.samples.size() / kMaxPlotRows);
  for (std::size_t i = 0; i < v.samples.size();
       i = (i + 1 < v.samples.size() && i + step >= v.samples.size())
               ? v.samples.size() - 1  // always end with the last sample
               : i + step) {
    const LogSample& x = v.samples[i];
    s << gnuplotNumber(x.t) << ' ' << gnuplotNumber(x.pos.x()) << ' ' << gnuplotNumber(x.pos.y())
      << ' ' << gnuplotNumber(x.pos.z()) << ' ' << gnuplotNumber(x.ref_pos.x()) << ' '
      << gnuplotNumber(x.ref_pos.y()) << ' ' << gnuplotNumber(x.ref_pos.z()) << ' '
      << gnuplotNumber(err[i]) << '\n';
  }
  writeText(file, s.str());
}

void writePathData(const std::vector<Eigen::Vector3d>& path, const std::filesystem::path& file) {
  std::ostringstream s;
  for (const auto& p : path)
    s << gnuplotNumber(p.x()) << ' ' << gnuplotNumber(p.y()) << ' ' << gnuplotNumber(p.z()) << '\n';
  writeText(file, s.str());
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
      const std::size_t step = std::max<std::size_t>(1, v.samples.size() / kMaxPlotRows);
      for (std::size_t k = 0; k < v.samples.size() && !near[i]; k += step)
        near[i] = close(v.samples[k].pos);
    }
  }
  return near;
}

// "v0.dat" (vehicle series), "p0.dat" (planned path), "g0.dat" (goal), built piece by piece:
// GCC 12's -Wrestrict misfires on operator+ chains with std::to_string.
std::string dataFile(char kind, std::size_t vehicle) {
  std::string name(1, kind);
  name += std::to_string(vehicle);
  name += ".dat";
  return name;
}

std::string axisName(int axis) {
  return axis == 0 ? "x" : axis == 1 ? "y" : "z";
}

// The paths over the obstacles along two world axes (top: x,y; side: x or y, z). plans: the
// planned paths and references too; a team's figures leave them out unless asked
// (render.team_plans): a grid planner's right angles, one per member, hide where they flew.
std::string pathPlot(const RunLog& log, int h, int v, const std::vector<ErrorReference>& refs,
                     bool plans) {
  const bool several = log.vehicles.size() > 1;
  std::ostringstream p;
  p << "plot ";
  bool first = true;
  const auto sep = [&] {
    if (!first) p << ", \\\n     ";
    first = false;
  };
  const std::string hc = std::to_string(h + 2), vc = std::to_string(v + 2);
  const std::string rh = std::to_string(h + 5), rv = std::to_string(v + 5);
  // A team's key names each kind of line once (32 vehicles made a key taller than the plot).
  const auto title = [&](std::size_t a, const std::string& one, const std::string& team) {
    return gnuplotString(!several ? one : a == 0 ? team : "");
  };
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    const VehicleLog& vl = log.vehicles[a];
    const std::string planned = hexColour(several ? agentColour(a) : kPlannedPathColour);
    const std::string id = std::to_string(a);
    if (!vl.samples.empty()) {
      if (plans && refs[a] == ErrorReference::Trajectory) {
        sep();
        p << "'v" << id << ".dat' using " << rh << ":" << rv
          << " with lines lw 1.2 dt (6,4) lc rgb '" << hexColour(kReferenceColour) << "' title "
          << gnuplotString(a == 0 ? "reference trajectory" : "");
      }
      sep();
      p << "'v" << id << ".dat' using " << hc << ":" << vc << ":8 with lines lw 3 lc palette title "
        << title(a, "flown (colour: tracking error)", "flown paths (colour: tracking error)");
    }
    if (plans && vl.planned_path.size() > 1) {
      sep();
      p << "'p" << id << ".dat' using " << h + 1 << ":" << v + 1
        << " with linespoints lw 1.8 pt 7 ps 0.5 lc rgb '" << planned << "' title "
        << title(a, "planned path", "planned paths (one colour each)");
    }
    sep();
    p << "'p" << id << ".dat' every ::0::0 using " << h + 1 << ":" << v + 1
      << " with points pt 7 ps 1.6 lc rgb '" << hexColour(several ? agentColour(a) : kStartColour)
      << "' title " << title(a, "start", "starts (one colour each)");
    sep();
    p << "'g" << id << ".dat' using " << h + 1 << ":" << v + 1
      << " with points pt 5 ps 1.6 lc rgb '" << hexColour(several ? agentColour(a) : kGoalColour)
      << "' title " << title(a, "goal", "goals");
  }
  return p.str();
}

// Each vehicle's data files in `work_dir`: samples with the record's errors, planned path, goal.
void writeFigureData(const RunRecord& record, const std::filesystem::path& work_dir) {
  const RunLog& log = record.log;
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    const VehicleLog& v = log.vehicles[a];
    writeVehicleData(v, record.metrics.tracking_errors[a], work_dir / dataFile('v', a));
    std::vector<Eigen::Vector3d> planned = v.planned_path;
    if (planned.empty() && !v.samples.empty()) planned.push_back(v.samples.front().pos);
    if (planned.empty()) planned.push_back(v.goal);
    writePathData(planned, work_dir / dataFile('p', a));
    writePathData({v.goal}, work_dir / dataFile('g', a));
  }
}

// The largest tracking error of any vehicle (the colour scale's top).
double largestError(const RunRecord& record) {
  double max_error = 0.0;
  for (const std::vector<double>& err : record.metrics.tracking_errors)
    for (double e : err) max_error = std::max(max_error, e);
  return max_error;
}

// The error figure's series (one per vehicle, from writeFigureData's files): the plot command,
// and the RMSE and arrival marks from each vehicle's metrics in the record.
struct ErrorSeries {
  std::string plot, marks;
};

ErrorSeries errorSeries(const RunRecord& record) {
  const RunLog& log = record.log;
  std::ostringstream error_plot, error_marks;
  error_plot << "plot ";
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    const VehicleLog& v = log.vehicles[a];
    const bool several = log.vehicles.size() > 1;
    const std::string colour =
        hexColour(several ? agentColour(a) : Eigen::Vector3f(0.13f, 0.35f, 0.65f));
    const FlightMetrics& m = record.metrics.vehicles[a];
    error_plot << (a ? ", \\\n     " : "") << "'v" << a
               << ".dat' using 1:8 with lines lw 2 lc rgb '" << colour << "' title "
               << gnuplotString((several ? v.name + ": " : std::string()) + "RMSE " +
                                gnuplotNumber(std::round(m.rmse_m * 1000) / 1000) + " m, max " +
                                gnuplotNumber(std::round(m.max_error_m * 1000) / 1000) + " m");
    error_marks << "set arrow from graph 0, first " << gnuplotNumber(m.rmse_m)
                << " to graph 1, first " << gnuplotNumber(m.rmse_m)
                << " nohead dt (4,4) lw 1 lc rgb '" << colour << "'\n";
    if (v.reached_goal && v.arrival_time >= 0)
      error_marks << "set arrow from first " << gnuplotNumber(v.arrival_time)
                  << ", graph 0 to first " << gnuplotNumber(v.arrival_time)
                  << ", graph 1 nohead dt (2,3) lw 1 lc rgb '#606060'\n"
                  << "set label " << gnuplotString("goal reached ") << " at first "
                  << gnuplotNumber(v.arrival_time)
                  << ", graph 0.5 right rotate by 90 offset -0.8,0 tc rgb '#404040' font ',9'\n";
    error_marks << "set label " << gnuplotString("RMSE") << " at graph 0.005, first "
                << gnuplotNumber(m.rmse_m) << " left offset 0,0.6 tc rgb '" << colour
                << "' font ',9'\n";
  }
  return {error_plot.str(), error_marks.str()};
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

// The top view's script: equal axes over the whole world.
std::string topView(const RunLog& log, const World& world, const std::string& planner,
                    const std::vector<ErrorReference>& refs, const std::string& palette,
                    bool plans) {
  const Eigen::Vector3d lo = world.bounds_min, hi = world.bounds_max;
  std::ostringstream top;
  top << kCommonStyle << palette << obstacleObjects(world, 0, 1) << "set title "
      << gnuplotString(
             std::string(plans ? "Top view: planned vs flown path (" : "Top view: flown paths (") +
             planner + "; darker obstacles are taller)")
      << "\n"
      << "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset size ratio -1\n"
      << "set xrange [" << gnuplotNumber(lo.x()) << ":" << gnuplotNumber(hi.x())
      << "]\nset yrange [" << gnuplotNumber(lo.y()) << ":" << gnuplotNumber(hi.y())
      << "]\nset key outside below horizontal center\n"
      << pathPlot(log, 0, 1, refs, plans) << "\n";
  return top.str();
}

// The side view's script, along the axis the flight crosses most (the other horizontal axis is
// depth).
std::string sideView(const RunLog& log, const World& world, const std::vector<ErrorReference>& refs,
                     const std::string& palette, bool plans) {
  const Eigen::Vector3d lo = world.bounds_min, hi = world.bounds_max;
  int along = 0;
  if (!log.vehicles.empty() && !log.vehicles[0].samples.empty()) {
    const Eigen::Vector3d d = log.vehicles[0].goal - log.vehicles[0].samples.front().pos;
    along = std::abs(d.y()) > std::abs(d.x()) ? 1 : 0;
  }
  std::ostringstream side;
  side << kCommonStyle << palette
       << obstacleObjects(world, along, 2, obstaclesNearPaths(world, log)) << "set title "
       << gnuplotString("Side view (looking along " + axisName(1 - along) + "; obstacles within " +
                        gnuplotNumber(kSideViewDepth) + " m of the paths only; height exaggerated)")
       << "\n"
       << "set xlabel '" << axisName(along) << " [m]'\nset ylabel 'z [m]'\nset size ratio 0.42\n"
       << "set xrange [" << gnuplotNumber(lo[along]) << ":" << gnuplotNumber(hi[along])
       << "]\nset yrange [" << gnuplotNumber(lo.z()) << ":" << gnuplotNumber(hi.z())
       << "]\nset key outside below horizontal center\n"
       << pathPlot(log, along, 2, refs, plans) << "\n";
  return side.str();
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
  writeFigureData(record, work.path());
  const ErrorSeries series = errorSeries(record);
  const double scale =
      errorScaleMax(largestError(record), errorScaleFloor(scenario.sim.goal_tolerance));
  const Eigen::Vector3d lo = world.bounds_min, hi = world.bounds_max;
  const std::string& planner_name = record.setup.primarySections().planner.name;
  const std::string planner = pathSourceName(scenario, planner_name);
  const std::string reference_name = referenceName(refs);
  const std::string palette = errorPalette(scale, "error to " + reference_name + " [m]");

  std::ostringstream error;
  error << kCommonStyle << "set title "
        << gnuplotString("Tracking error against " + reference_name + " (" + planner + ")")
        << "\nset xlabel 'time [s]'\nset ylabel 'position error [m]'\nset yrange [0:*]\nset xrange "
           "[0:*]\n"
        << "set key top right\n"
        << series.marks << series.plot << "\n";

  const bool plans = log.vehicles.size() <= 1 || scenario.render.team_plans;
  // The top view keeps equal axes: the canvas height follows the world's aspect ratio (the
  // plot is ~760 px wide; title, axes and key take ~190 px).
  const double aspect = (hi.y() - lo.y()) / std::max(1e-9, hi.x() - lo.x());
  const int top_height = 2 * static_cast<int>(std::clamp(95.0 + 380.0 * aspect, 250.0, 700.0));
  std::string script =
      plotBoth("error", 1000, 480, error.str()) + "reset\n" +
      plotBoth("top", 1000, top_height, topView(log, world, planner, refs, palette, plans)) +
      "reset\n" + plotBoth("side", 1000, 560, sideView(log, world, refs, palette, plans));
  runGnuplot(script, work.path());
  const std::vector<std::string> names = {"error", "top", "side"};
  for (const auto& n : names)
    for (const char* ext : {".png", ".svg"}) work.publish(n + ext, dir / (n + ext));
  return names;
}

}  // namespace cosim
