#include "experiments/reproduce/seed004_encounters.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <vector>

#include "planning/mapf/goal_distance_table.h"
#include "planning/mapf/mapf_graph.h"

namespace cosim::reproduce {

namespace {

// Where a robot is at step t (it stays at its last cell after its path ends).
const Cell& at(const MapfPath& p, std::size_t t) {
  return p[std::min(t, p.size() - 1)];
}

std::size_t longest(const MapfTrial& trial) {
  std::size_t n = 0;
  for (const MapfPath& p : trial.paths) n = std::max(n, p.size());
  return n;
}

}  // namespace

int mutualRetreatSteps(const MapfInstance& instance, const MapfTrial& trial) {
  const int n = static_cast<int>(trial.paths.size());
  if (n < 2) return 0;
  for (const MapfPath& p : trial.paths)
    if (p.empty()) return 0;
  const MapfGraph graph = MapfGraph::fromGrid(instance.grid, instance.connectivity);
  std::vector<int> goals;
  for (const Cell& g : instance.goals) goals.push_back(graph.vertexOf(g));
  const GoalDistanceTable distance(graph, goals);
  auto dist = [&](int a, const Cell& c) { return distance(a, graph.vertexOf(c)); };
  int steps = 0;
  for (std::size_t t = 1; t < longest(trial); ++t) {
    std::vector<bool> retreats(n);
    for (int a = 0; a < n; ++a)
      retreats[a] = dist(a, at(trial.paths[a], t)) > dist(a, at(trial.paths[a], t - 1));
    bool mutual = false;
    for (int a = 0; a < n && !mutual; ++a)
      for (int b = a + 1; b < n && !mutual; ++b) {
        const Cell &pa = at(trial.paths[a], t - 1), &pb = at(trial.paths[b], t - 1);
        mutual =
            retreats[a] && retreats[b] && std::abs(pa.x - pb.x) <= 2 && std::abs(pa.y - pb.y) <= 2;
      }
    steps += mutual;
  }
  return steps;
}

bool cyclesThroughJointPositions(const MapfTrial& trial, int tail) {
  const std::size_t length = longest(trial);
  if (trial.paths.empty() || length < 2) return false;
  for (const MapfPath& p : trial.paths)
    if (p.empty()) return false;
  auto joint = [&](std::size_t t) {
    std::vector<int> key;
    for (const MapfPath& p : trial.paths) key.insert(key.end(), {at(p, t).x, at(p, t).y});
    return key;
  };
  bool moving = false;
  for (std::size_t t = length > static_cast<std::size_t>(tail) ? length - tail : 1; t < length; ++t)
    moving |= joint(t) != joint(t - 1);
  if (!moving) return false;
  std::map<std::vector<int>, int> seen;
  for (std::size_t t = 0; t < length; ++t)
    if (++seen[joint(t)] >= 3) return true;
  return false;
}

}  // namespace cosim::reproduce
