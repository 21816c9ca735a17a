#include "planning/grid/grid_passage_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <queue>
#include <vector>

namespace cosim {

namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
  char buf[320];
  std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
  return buf;
}

// Each cell centre's distance to the nearest obstacle surface (and, in 3D, to the floor),
// capped at `cap`; -inf for centres outside the bounds.
std::vector<double> centreClearances(const World& world, const OccupancyGrid& g, bool planar,
                                     double cap) {
  std::vector<double> clearance(g.cellCount(), cap);
  for (std::size_t i = 0; i < clearance.size(); ++i) {
    Eigen::Vector3d c = g.cellCenter(g.cellAt(i));
    if (planar) c.z() = std::clamp(c.z(), world.bounds_min.z(), world.bounds_max.z());
    if (!world.insideBounds(c))
      clearance[i] = -std::numeric_limits<double>::infinity();
    else if (!planar)
      clearance[i] = std::min(cap, c.z() - world.bounds_min.z());
  }
  for (const Obstacle& o : world.obstacles) {
    Eigen::Vector3d lo, hi;
    o.boundingBox(cap, lo, hi);
    const Cell a = g.cellOf(lo), b = g.cellOf(hi);
    for (int z = std::max(0, a.z); z <= std::min(g.nz() - 1, b.z); ++z)
      for (int y = std::max(0, a.y); y <= std::min(g.ny() - 1, b.y); ++y)
        for (int x = std::max(0, a.x); x <= std::min(g.nx() - 1, b.x); ++x) {
          double& c = clearance[g.index(x, y, z)];
          c = std::min(c, o.signedDistance(g.cellCenter({x, y, z})));
        }
  }
  return clearance;
}

// The least clearance at the quarter points of the segment [a, b] (enough to find an obstacle
// the segment crosses between two cell centres; a diagnosis, not a collision test).
double innerClearance(const World& world, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  double least = std::numeric_limits<double>::infinity();
  for (const double t : {0.25, 0.5, 0.75})
    least = std::min(least, world.distanceToObstacles(a + t * (b - a)));
  return least;
}

}  // namespace

WidestPassage widestPassage(const World& world, const OccupancyGrid& layout, const Cell& start,
                            const Cell& goal, bool planar, double cap) {
  const std::vector<double> clearance = centreClearances(world, layout, planar, cap);
  // Bottleneck Dijkstra: best[v] is the largest least-clearance of a chain from start to v.
  std::vector<double> best(clearance.size(), -std::numeric_limits<double>::infinity());
  std::priority_queue<std::pair<double, std::size_t>> open;
  const std::size_t s = layout.index(start), t = layout.index(goal);
  best[s] = std::min(clearance[s], clearance[t]);
  open.emplace(best[s], s);
  const int zr = layout.is3D() ? 1 : 0;
  const double r = layout.cellSize();
  while (!open.empty()) {
    const auto [w, u] = open.top();
    open.pop();
    if (w < best[u]) continue;  // outdated entry
    if (u == t || w <= 0.0) break;
    const Cell c = layout.cellAt(u);
    for (int dz = -zr; dz <= zr; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!layout.inside(c.x + dx, c.y + dy, c.z + dz)) continue;
          const std::size_t v = layout.index(c.x + dx, c.y + dy, c.z + dz);
          double through = std::min(w, clearance[v]);
          if (through <= best[v]) continue;
          // Two balls of the centres' clearances that do not cover the edge leave room for an
          // obstacle between the centres (a thin wall): then the edge's inner points count too.
          const double length = r * std::sqrt(static_cast<double>(dx * dx + dy * dy + dz * dz));
          if (clearance[u] + clearance[v] < length)
            through = std::min(through, innerClearance(world, layout.cellCenter(c),
                                                       layout.cellCenter(layout.cellAt(v))));
          if (through <= best[v]) continue;
          best[v] = through;
          open.emplace(through, v);
        }
  }
  WidestPassage result;
  result.joined = best[t] > 0.0;
  result.clearance = std::max(0.0, best[t]);
  result.capped = best[t] >= cap;
  return result;
}

const char* blockingName(OccupancyGrid::Blocking blocking) {
  switch (blocking) {
    case OccupancyGrid::Blocking::Exact:
      return "exact";
    case OccupancyGrid::Blocking::Centre:
      return "centre";
    case OccupancyGrid::Blocking::AnyPoint:
      break;
  }
  return "cell";
}

const char* pathEndName(PathEnd end) {
  return end == PathEnd::Start ? "start" : "goal";
}

std::string explainNoGridPath(const World& world, const OccupancyGrid& grid, const Cell& start,
                              const Cell& goal, double inflation, bool planar,
                              bool search_exhausted, const std::string& search_message,
                              OccupancyGrid::Blocking blocking) {
  const double r = grid.cellSize();
  const std::string where =
      format("at resolution %g m, obstacles inflated by %g m (vehicle radius + margin)", r,
             inflation) +
      ", cell_blocking " + blockingName(blocking);
  if (!search_exhausted) return search_message + " " + where;
  // Look a little beyond the inflation: enough to tell "too narrow" from "too coarse".
  const WidestPassage p = widestPassage(world, grid, start, goal, planar, inflation + 2.0 * r);
  if (!p.joined)
    return "no path " + where +
           ": no chain of cells outside the obstacles joins start and goal at this resolution "
           "(walled off, or every gap is narrower than a cell)";
  if (p.clearance <= inflation)
    return "no path " + where +
           format(
               ": the widest passage found (measured at cell centres) keeps only %.3g m from "
               "obstacles (a gap of about %.3g m), no more than the inflation; lower the "
               "margin or use a smaller vehicle",
               p.clearance, 2.0 * p.clearance);
  return "no path " + where + ": a passage keeping " + (p.capped ? "at least " : "") +
         format(
             "%.3g m from obstacles exists, more than the inflation, so the grid is too coarse "
             "or too conservative for it; try a finer resolution (e.g. %g m)",
             p.clearance, 0.5 * r) +
         (blocking == OccupancyGrid::Blocking::AnyPoint ? " or cell_blocking exact" : "");
}

std::string explainBlockedEnd(const World& world, const OccupancyGrid& grid, PathEnd which,
                              const Eigen::Vector3d& p, double inflation, bool planar) {
  const Cell cell = grid.cellOf(p);
  Eigen::Vector3d centre = grid.cellCenter(cell);
  if (planar) centre.z() = p.z();
  const std::string point = format("(%g, %g, %g)", p.x(), p.y(), p.z());
  if (!grid.inside(cell) || !world.insideBounds(centre))
    return std::string(pathEndName(which)) + " " + point +
           format(" is outside the world bounds at resolution %g m", grid.cellSize());
  double d = world.distanceToObstacles(centre);
  if (!planar) d = std::min(d, centre.z() - world.bounds_min.z());
  double own = world.distanceToObstacles(p);
  if (!planar) own = std::min(own, p.z() - world.bounds_min.z());
  return std::string(pathEndName(which)) +
         format(
             " cell is blocked at resolution %g m, obstacles inflated by %g m (vehicle radius "
             "+ margin): its centre is %g m from the nearest obstacle or the floor; the point ",
             grid.cellSize(), inflation, d) +
         point + format(" itself is %g m away", own) +
         (own > inflation ? " (a finer resolution may free it)" : " (move it or lower the margin)");
}

}  // namespace cosim
