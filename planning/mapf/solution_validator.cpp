#include "planning/mapf/solution_validator.h"

#include <algorithm>
#include <cstdlib>

namespace cosim {

namespace {

std::string describe(const Cell& c, bool three_d) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string s(1, '(');
  s.append(std::to_string(c.x)).append(", ").append(std::to_string(c.y));
  if (three_d) s.append(", ").append(std::to_string(c.z));
  return s.append(")");
}

// Where agent i is at time t: its path, then its goal for ever.
const Cell& positionAt(const MapfPath& path, int t) {
  return path[std::min<std::size_t>(static_cast<std::size_t>(t), path.size() - 1)];
}

// The rule of a step (dx, dy, dz), each in -1..1, not all 0: "" if legal, else the problem.
std::string stepProblem(const MapfInstance& inst, const Cell& p, int dx, int dy, int dz) {
  const int axes = std::abs(dx) + std::abs(dy) + std::abs(dz);
  const int c = inst.connectivity;
  // Most axes one step may change: 4 and 6 move along one axis, 8 and 18 along two, 26 three.
  const int allowed = (c == 4 || c == 6) ? 1 : (c == 8 || c == 18) ? 2 : 3;
  if (axes > allowed)
    return axes == 2 ? "diagonal step on a " + std::to_string(c) + "-connected grid"
                     : "step along " + std::to_string(axes) + " axes on a " + std::to_string(c) +
                           "-connected grid";
  if (axes == 1) return "";
  // No corner cutting: every other cell of the box the step spans must be free.
  for (int mz = 0; mz <= std::abs(dz); ++mz)
    for (int my = 0; my <= std::abs(dy); ++my)
      for (int mx = 0; mx <= std::abs(dx); ++mx)
        if (inst.grid.blocked(p.x + mx * dx, p.y + my * dy, p.z + mz * dz))
          return "diagonal step past a wall corner from " + describe(p, inst.grid.is3D());
  return "";
}

void checkSteps(const MapfInstance& inst, int agent, const MapfPath& path,
                std::vector<std::string>& problems) {
  const bool three_d = inst.grid.is3D();
  const std::string who = "agent " + std::to_string(agent);
  if (path.empty()) {
    problems.push_back(who + ": empty path");
    return;
  }
  if (path.front() != inst.starts[agent])
    problems.push_back(who + ": starts at " + describe(path.front(), three_d) +
                       ", not at its start " + describe(inst.starts[agent], three_d));
  if (path.back() != inst.goals[agent])
    problems.push_back(who + ": ends at " + describe(path.back(), three_d) + ", not at its goal " +
                       describe(inst.goals[agent], three_d));
  for (std::size_t t = 0; t < path.size(); ++t) {
    const Cell& c = path[t];
    const std::string at = who + " at t=" + std::to_string(t) + ": ";
    if (inst.grid.blocked(c)) {
      problems.push_back(at + "in a blocked or off-map cell " + describe(c, three_d));
      continue;
    }
    if (t == 0) continue;
    const Cell& p = path[t - 1];
    const int dx = c.x - p.x, dy = c.y - p.y, dz = c.z - p.z;
    if (std::abs(dx) > 1 || std::abs(dy) > 1 || std::abs(dz) > 1) {
      problems.push_back(at + "jumps from " + describe(p, three_d) + " to " + describe(c, three_d));
    } else if (dx != 0 || dy != 0 || dz != 0) {
      const std::string problem = stepProblem(inst, p, dx, dy, dz);
      if (!problem.empty()) problems.push_back(at + problem);
    }
  }
}

}  // namespace

const char* conflictKindName(MapfConflict::Kind kind) {
  switch (kind) {
    case MapfConflict::Kind::kVertex:
      return "vertex";
    case MapfConflict::Kind::kSwap:
      return "swap";
    case MapfConflict::Kind::kCrossingDiagonal:
      return "crossing_diagonal";
  }
  return "?";
}

MapfValidation validateMapfSolution(const MapfInstance& inst, const std::vector<MapfPath>& paths) {
  MapfValidation v;
  const int n = inst.agentCount();
  if (static_cast<int>(paths.size()) != n) {
    v.problems.push_back("expected " + std::to_string(n) + " paths, got " +
                         std::to_string(paths.size()));
    return v;
  }
  for (int i = 0; i < n; ++i) checkSteps(inst, i, paths[i], v.problems);
  if (!v.problems.empty()) return v;  // conflicts are meaningless on illegal paths

  std::size_t horizon = 1;
  for (const auto& p : paths) horizon = std::max(horizon, p.size());
  // Occupant of each cell at time t, and of each half-step point (doubled coordinates) between
  // t and t + 1; entries are valid when their stamp equals the current one.
  const std::size_t w = inst.grid.nx(), h = inst.grid.ny(), d = inst.grid.nz();
  std::vector<int> cell_agent(w * h * d), cell_stamp(cell_agent.size(), -1);
  // Doubled coordinates: 2w x 2h per layer, 2d layers (one layer when the grid is 2D).
  const std::size_t mid_layers = inst.grid.is3D() ? 2 * d : 1;
  std::vector<int> mid_agent(4 * w * h * mid_layers), mid_stamp(mid_agent.size(), -1);
  for (int t = 0; t < static_cast<int>(horizon); ++t) {
    for (int i = 0; i < n; ++i) {
      const Cell& c = positionAt(paths[i], t);
      const std::size_t k = (static_cast<std::size_t>(c.z) * h + c.y) * w + c.x;
      if (cell_stamp[k] == t)
        v.conflicts.push_back({MapfConflict::Kind::kVertex, cell_agent[k], i, t, c});
      else
        cell_stamp[k] = t, cell_agent[k] = i;
    }
    if (t + 1 == static_cast<int>(horizon)) break;
    for (int i = 0; i < n; ++i) {
      const Cell& a = positionAt(paths[i], t);
      const Cell& b = positionAt(paths[i], t + 1);
      if (a == b) continue;
      // Doubled midpoint; it lies strictly between cell centres, so waiting agents never hit it.
      const std::size_t k =
          (static_cast<std::size_t>(a.z + b.z) * (2 * h) + (a.y + b.y)) * (2 * w) + (a.x + b.x);
      if (mid_stamp[k] != t) {
        mid_stamp[k] = t, mid_agent[k] = i;
        continue;
      }
      const int j = mid_agent[k];
      const bool swap = positionAt(paths[j], t) == b && positionAt(paths[j], t + 1) == a;
      v.conflicts.push_back(
          {swap ? MapfConflict::Kind::kSwap : MapfConflict::Kind::kCrossingDiagonal, j, i, t,
           positionAt(paths[j], t)});
    }
  }
  return v;
}

}  // namespace cosim
