#include "planning/mapf/solution_validator.h"

#include <algorithm>
#include <cstdlib>

namespace cosim {

namespace {

std::string describe(const Cell& c) {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string s(1, '(');
  s.append(std::to_string(c.x)).append(", ").append(std::to_string(c.y)).append(")");
  return s;
}

// Where agent i is at time t: its path, then its goal for ever.
const Cell& positionAt(const MapfPath& path, int t) {
  return path[std::min<std::size_t>(static_cast<std::size_t>(t), path.size() - 1)];
}

void checkSteps(const MapfInstance& inst, int agent, const MapfPath& path,
                std::vector<std::string>& problems) {
  const std::string who = "agent " + std::to_string(agent);
  if (path.empty()) {
    problems.push_back(who + ": empty path");
    return;
  }
  if (path.front() != inst.starts[agent])
    problems.push_back(who + ": starts at " + describe(path.front()) + ", not at its start " +
                       describe(inst.starts[agent]));
  if (path.back() != inst.goals[agent])
    problems.push_back(who + ": ends at " + describe(path.back()) + ", not at its goal " +
                       describe(inst.goals[agent]));
  for (std::size_t t = 0; t < path.size(); ++t) {
    const Cell& c = path[t];
    const std::string at = who + " at t=" + std::to_string(t) + ": ";
    if (inst.grid.blocked(c.x, c.y)) {
      problems.push_back(at + "in a blocked or off-map cell " + describe(c));
      continue;
    }
    if (t == 0) continue;
    const Cell& p = path[t - 1];
    const int dx = c.x - p.x, dy = c.y - p.y;
    if (std::abs(dx) > 1 || std::abs(dy) > 1 || c.z != p.z) {
      problems.push_back(at + "jumps from " + describe(p) + " to " + describe(c));
    } else if (dx != 0 && dy != 0) {
      if (inst.connectivity == 4)
        problems.push_back(at + "diagonal step on a 4-connected grid");
      else if (inst.grid.blocked(p.x + dx, p.y) || inst.grid.blocked(p.x, p.y + dy))
        problems.push_back(at + "diagonal step past a wall corner from " + describe(p));
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
  const int w = inst.grid.nx(), h = inst.grid.ny();
  std::vector<int> cell_agent(static_cast<std::size_t>(w) * h), cell_stamp(cell_agent.size(), -1);
  std::vector<int> mid_agent(static_cast<std::size_t>(2 * w) * (2 * h)),
      mid_stamp(mid_agent.size(), -1);
  for (int t = 0; t < static_cast<int>(horizon); ++t) {
    for (int i = 0; i < n; ++i) {
      const Cell& c = positionAt(paths[i], t);
      const std::size_t k = static_cast<std::size_t>(c.y) * w + c.x;
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
      const std::size_t k = static_cast<std::size_t>(a.y + b.y) * (2 * w) + (a.x + b.x);
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
