#include "planning/swarm/planar_layer.h"

#include <cstdio>

namespace cosim {

PlanarLayer planarLayerFor(const GridQuery& query) {
  PlanarLayer out;
  const OccupancyGrid& g = *query.grid;
  const Cell& s = query.start;
  const Cell& t = query.goal;
  if (g.blocked(s) || g.blocked(t)) {
    out.error =
        std::string(g.blocked(s) ? "start" : "goal") + " cell is blocked or outside the grid";
    out.error_status = g.blocked(s) ? PlannerStatus::InvalidStart : PlannerStatus::InvalidGoal;
    return out;
  }
  out.layer = s.z;
  out.grid = OccupancyGrid(g.nx(), g.ny(), 1, g.cellSize(),
                           g.origin() + Eigen::Vector3d(0, 0, g.cellSize() * s.z));
  for (int y = 0; y < g.ny(); ++y)
    for (int x = 0; x < g.nx(); ++x)
      if (g.blocked(x, y, s.z)) out.grid.setBlocked(x, y, 0, true);
  out.start = {s.x, s.y, 0};
  out.goal = {t.x, t.y, 0};
  const int step = t.z > s.z ? 1 : -1;
  for (int z = s.z; z != t.z;) {
    z += step;
    if (g.blocked(t.x, t.y, z)) {
      // In metres, as the user gave them: grid layers are an internal detail.
      char where[160];
      std::snprintf(where, sizeof where,
                    "this planner plans at the start's height (z %.3g m) and climbs to the "
                    "goal's; the goal's column is blocked at z %.3g m",
                    g.cellCenter(s).z(), g.cellCenter({t.x, t.y, z}).z());
      out.error = where;
      out.error_status = PlannerStatus::InvalidGoal;
      return out;
    }
    out.climb.push_back({t.x, t.y, z});
  }
  if (out.grid.blocked(out.goal)) {
    out.error = "the goal's column is blocked on the start's layer";
    out.error_status = PlannerStatus::InvalidGoal;
  }
  return out;
}

std::vector<Cell> liftFromLayer(const std::vector<Cell>& cells, const PlanarLayer& layer) {
  std::vector<Cell> out;
  out.reserve(cells.size() + layer.climb.size());
  for (Cell c : cells) {
    c.z = layer.layer;
    out.push_back(c);
  }
  out.insert(out.end(), layer.climb.begin(), layer.climb.end());
  return out;
}

}  // namespace cosim
