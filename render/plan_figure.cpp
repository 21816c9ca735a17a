#include "render/plan_figure.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

namespace {

// The footprint of an obstacle from above, as a closed outline (a box's rotated rectangle; a
// circle as 32 sides for cylinders and spheres).
std::vector<Eigen::Vector2d> footprint(const Obstacle& o) {
  std::vector<Eigen::Vector2d> outline;
  if (o.type == ObstacleType::Box) {
    const double c = std::cos(o.yaw_deg * M_PI / 180.0), s = std::sin(o.yaw_deg * M_PI / 180.0);
    const double hx = 0.5 * o.size.x(), hy = 0.5 * o.size.y();
    for (const auto& [dx, dy] : {std::pair{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}})
      outline.emplace_back(o.pos.x() + c * dx - s * dy, o.pos.y() + s * dx + c * dy);
  } else {
    for (int k = 0; k < 32; ++k) {
      const double a = 2.0 * M_PI * k / 32;
      outline.emplace_back(o.pos.x() + o.radius * std::cos(a), o.pos.y() + o.radius * std::sin(a));
    }
  }
  outline.push_back(outline.front());
  return outline;
}

// The bottom and top of an obstacle.
std::pair<double, double> heightRange(const Obstacle& o) {
  const double half = o.type == ObstacleType::Box        ? 0.5 * o.size.z()
                      : o.type == ObstacleType::Cylinder ? 0.5 * o.height
                                                         : o.radius;
  return {o.pos.z() - half, o.pos.z() + half};
}

// Horizontal distance from p to segment [a, b].
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// True if some corner of the footprint, or its centre, comes within `reach` of the path's
// footprint (the path as a polyline from above).
bool nearPath(const std::vector<Eigen::Vector2d>& outline, const Eigen::Vector2d& centre,
              const std::vector<Eigen::Vector2d>& path, double reach) {
  std::vector<Eigen::Vector2d> points = outline;
  points.push_back(centre);
  for (const Eigen::Vector2d& p : points)
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
      if (distanceToSegment(p, path[i], path[i + 1]) <= reach) return true;
  return false;
}

std::string point(double a, double b) {
  return gnuplotNumber(a) + " " + gnuplotNumber(b) + "\n";
}

}  // namespace

void writePlanFigure(const World& world, const std::vector<Eigen::Vector3d>& path,
                     const Eigen::Vector3d& start, const Eigen::Vector3d& goal,
                     const std::string& title, const std::filesystem::path& out_base) {
  const GnuplotScratch scratch(out_base, "plan");
  const Eigen::Vector3d lo = world.bounds_min, hi = world.bounds_max;
  // The side view looks across the trip's longer horizontal extent.
  const Eigen::Vector3d trip = goal - start;
  const int along = std::abs(trip.x()) >= std::abs(trip.y()) ? 0 : 1;
  std::vector<Eigen::Vector2d> flat;
  for (const auto& p : path.empty() ? std::vector<Eigen::Vector3d>{start, goal} : path)
    flat.push_back(p.head<2>());

  std::ostringstream top, side, line;
  for (const Obstacle& o : world.obstacles) {
    const std::vector<Eigen::Vector2d> outline = footprint(o);
    for (const auto& p : outline) top << point(p.x(), p.y());
    top << "\n";
    if (!nearPath(outline, o.pos.head<2>(), flat, kPlanSideViewReach)) continue;
    double a0 = outline.front()[along], a1 = a0;
    for (const auto& p : outline) {
      a0 = std::min(a0, p[along]);
      a1 = std::max(a1, p[along]);
    }
    const auto [z0, z1] = heightRange(o);
    side << point(a0, z0) << point(a1, z0) << point(a1, z1) << point(a0, z1) << point(a0, z0)
         << "\n";
  }
  for (const auto& p : path) line << gnuplotNumber(p.x()) << " " << point(p.y(), p.z());
  const std::string ends = gnuplotNumber(start.x()) + " " + point(start.y(), start.z()) +
                           gnuplotNumber(goal.x()) + " " + point(goal.y(), goal.z());
  // gnuplot refuses to plot an empty file: a point outside the ranges stands in for "nothing".
  const std::string none = point(lo.x() - 1e6, lo.y() - 1e6);
  scratch.write("top.dat", top.str().empty() ? none : top.str());
  scratch.write("side.dat", side.str().empty() ? none : side.str());
  scratch.write("path.dat",
                line.str().empty() ? gnuplotNumber(lo.x() - 1e6) + " " + none : line.str());
  scratch.write("ends.dat", ends);

  const char* axis_name[] = {"x [m]", "y [m]"};
  // The run's visual language (render/overlay_palette.h), as in a run's figures.
  const std::string path_style =
      "with linespoints lw 2.5 pt 7 ps 0.5 lc rgb '" + hexColour(kPlannedPathColour) + "'";
  const std::string obstacle_style = "with filledcurves closed fc rgb '" +
                                     std::string(kObstacleFill) +
                                     "' fs solid 0.55 border lc rgb '" + kObstacleEdge + "'";
  const std::string start_colour = " lc rgb '" + hexColour(kStartColour) + "'";
  const std::string goal_colour = " lc rgb '" + hexColour(kGoalColour) + "'";
  std::ostringstream body;
  body << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid lc rgb '#e4e4e4'\n"
       << "set tics out nomirror\nset key top left opaque box\n"
       << "set multiplot layout 1,2 title " << gnuplotString(title) << "\n"
       << "set title 'from above'\nset size ratio -1\nset xlabel 'x [m]'\nset ylabel 'y [m]'\n"
       << "set xrange [" << gnuplotNumber(lo.x()) << ":" << gnuplotNumber(hi.x()) << "]\n"
       << "set yrange [" << gnuplotNumber(lo.y()) << ":" << gnuplotNumber(hi.y()) << "]\n"
       << "plot 'top.dat' using 1:2 " << obstacle_style << " title 'obstacles', "
       << "'path.dat' using 1:2 " << path_style << " title 'planned path', "
       << "'ends.dat' every ::0::0 using 1:2 with points pt 7 ps 1.6" << start_colour
       << " title 'start', 'ends.dat' every ::1::1 using 1:2 with points pt 9 ps 1.8" << goal_colour
       << " title 'goal'\n"
       << "set title "
       << gnuplotString("from the side (obstacles within " + gnuplotNumber(kPlanSideViewReach) +
                        " m of the path)")
       << "\nset size noratio\nset xlabel '" << axis_name[along] << "'\nset ylabel 'z [m]'\n"
       << "set xrange [" << gnuplotNumber(lo[along]) << ":" << gnuplotNumber(hi[along]) << "]\n"
       << "set yrange [" << gnuplotNumber(lo.z()) << ":" << gnuplotNumber(hi.z()) << "]\n"
       << "plot 'side.dat' using 1:2 " << obstacle_style << " title 'obstacles', "
       << "'path.dat' using " << along + 1 << ":3 " << path_style << " title 'planned path', "
       << "'ends.dat' every ::0::0 using " << along + 1 << ":3 with points pt 7 ps 1.6"
       << start_colour << " notitle, 'ends.dat' every ::1::1 using " << along + 1
       << ":3 with points pt 9 ps 1.8" << goal_colour << " notitle\n"
       << "unset multiplot\n";
  runGnuplot(plotBoth("plan", 1400, 640, body.str()), scratch.dir());
  scratch.publish("plan");
}

}  // namespace cosim
