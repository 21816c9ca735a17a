#include "planning/sampling/prm.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>

#include "planning/sampling/nearest_neighbor_index.h"

namespace cosim {

namespace {

struct Roadmap {
  struct Edge {
    std::uint32_t to;
    double length;
  };
  std::vector<std::vector<Edge>> edges;
  std::vector<std::uint32_t> component;  // union-find parents

  std::uint32_t find(std::uint32_t v) {
    while (component[v] != v) v = component[v] = component[component[v]];
    return v;
  }
  void connect(std::uint32_t a, std::uint32_t b, double length) {
    edges[a].push_back({b, length});
    edges[b].push_back({a, length});
    const std::uint32_t ra = find(a), rb = find(b);
    if (ra != rb) component[std::max(ra, rb)] = std::min(ra, rb);
  }
};

// A* over the roadmap from node 0 (start) to node 1 (goal); empty if they are not connected.
std::vector<std::uint32_t> shortestRoute(const Roadmap& map, const NearestNeighborIndex& nodes) {
  const std::size_t n = map.edges.size();
  const Eigen::Vector3d& goal = nodes.point(1);
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<std::uint32_t> parent(n, 0);
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  g[0] = 0.0;
  open.emplace((nodes.point(0) - goal).norm(), 0);
  while (!open.empty()) {
    const auto [f, u] = open.top();
    open.pop();
    if (u == 1) break;
    if (f > g[u] + (nodes.point(u) - goal).norm() + 1e-12) continue;  // stale entry
    for (const auto& e : map.edges[u]) {
      const double c = g[u] + e.length;
      if (c < g[e.to]) {
        g[e.to] = c;
        parent[e.to] = u;
        open.emplace(c + (nodes.point(e.to) - goal).norm(), e.to);
      }
    }
  }
  std::vector<std::uint32_t> route;
  if (g[1] == std::numeric_limits<double>::infinity()) return route;
  for (std::uint32_t v = 1; v != 0; v = parent[v]) route.push_back(v);
  route.push_back(0);
  std::reverse(route.begin(), route.end());
  return route;
}

}  // namespace

PlanResult Prm::solve(const PlanningProblem& problem, const StopToken& stop) {
  SamplingContext ctx(problem, stop);
  if (!ctx.invalid().empty()) return ctx.reject();
  const SamplingOptions& o = options_.common;
  NearestNeighborIndex nodes(initialCapacity(o));
  Roadmap map;
  std::vector<std::pair<std::uint32_t, double>> neighbours;
  double edges = 0;

  auto addNode = [&](const Eigen::Vector3d& p) {
    nodes.nearestK(p, static_cast<std::size_t>(options_.k), neighbours);
    const std::uint32_t id = nodes.add(p);
    map.edges.emplace_back();
    map.component.push_back(id);
    for (const auto& [other, d2] : neighbours) {
      const double d = std::sqrt(d2);
      if (d > o.step || !ctx.segmentFree(nodes.point(other), p)) continue;
      map.connect(id, other, d);
      ++edges;
    }
  };
  addNode(ctx.start());
  addNode(ctx.goal());

  double iterations = 0;
  while (!ctx.shouldStop(o, nodes.size(), map.find(0) == map.find(1))) {
    ++iterations;
    const Eigen::Vector3d p = ctx.sample(0.0);
    if (ctx.pointFree(p)) addNode(p);
  }

  PlanResult result;
  if (map.find(0) == map.find(1))
    for (std::uint32_t v : shortestRoute(map, nodes))
      result.path.waypoints.push_back(nodes.point(v));
  result.counters["iterations"] = iterations;
  result.counters["nodes"] = static_cast<double>(nodes.size());
  result.counters["edges"] = edges;
  return ctx.finish(std::move(result), o);
}

}  // namespace cosim
