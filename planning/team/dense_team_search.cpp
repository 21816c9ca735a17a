#include "planning/team/dense_team_search.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>
#include <queue>
#include <tuple>
#include <unordered_map>

#include "planning/team/ellipsoid_conflict.h"
#include "planning/team/ellipsoid_reservations.h"

namespace cosim {

namespace {

constexpr int kUnreachable = std::numeric_limits<int>::max();
// The reservations' step field holds 16 bits: searches end well before.
constexpr int kMaxStep = 60000;

std::vector<int> distancesTo(const MapfGraph& graph, int goal) {
  std::vector<int> d(graph.vertexCount(), kUnreachable);
  std::deque<int> open{goal};
  d[goal] = 0;
  while (!open.empty()) {
    const int v = open.front();
    open.pop_front();
    for (const int u : graph.neighbours(v))
      if (d[u] == kUnreachable) {
        d[u] = d[v] + 1;
        open.push_back(u);
      }
  }
  return d;
}

struct ReservationSearchNode {
  int vertex, t, g, parent;
};

std::uint64_t stateKey(int vertex, int t) {
  return static_cast<std::uint64_t>(static_cast<std::uint32_t>(t)) << 32 |
         static_cast<std::uint32_t>(vertex);
}

enum class Outcome { Found, NoPath, OutOfBudget };

// Space-time A* for one agent around the reservations: waiting or one move per step, cost one
// step each, ending at the goal from a step after which nothing passes close to it. Beyond the
// reservations' last move nothing changes, so states are then merged by vertex and the search
// is finite.
Outcome searchAgent(const DenseTeamQuery& q, const EllipsoidReservations& reserved,
                    const std::vector<int>& h, int start, int goal, std::vector<int>& path,
                    long& expansions) {
  const int goal_last = reserved.lastConflictStanding(goal);
  if (goal_last == EllipsoidReservations::kForever || h[start] == kUnreachable)
    return Outcome::NoPath;
  const int horizon = reserved.staticFrom();
  const auto merged = [&](int t) { return std::min(t, horizon); };
  std::vector<ReservationSearchNode> nodes{{start, 0, 0, -1}};
  std::unordered_map<std::uint64_t, std::pair<int, bool>> states;  // g, closed
  states[stateKey(start, 0)] = {0, false};
  using Entry = std::tuple<int, int, int>;  // f, -t (deepest first), node
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  open.emplace(h[start], 0, 0);
  long local = 0;
  while (!open.empty()) {
    const int index = std::get<2>(open.top());
    open.pop();
    const ReservationSearchNode n = nodes[index];
    auto& record = states[stateKey(n.vertex, merged(n.t))];
    if (record.second || n.g > record.first) continue;
    record.second = true;
    if (n.vertex == goal && n.t > goal_last) {
      path.clear();
      for (int i = index; i >= 0; i = nodes[i].parent) path.push_back(nodes[i].vertex);
      std::reverse(path.begin(), path.end());
      return Outcome::Found;
    }
    ++expansions;
    if (++local > q.max_expansions_per_agent || n.t >= kMaxStep ||
        ((local & 255) == 0 && q.deadline && q.deadline->expired()))
      return Outcome::OutOfBudget;
    const auto tryStep = [&](int next) {
      if (h[next] == kUnreachable || reserved.moveConflicts(n.vertex, next, n.t)) return;
      const int g = n.g + 1;
      const auto [it, inserted] = states.try_emplace(stateKey(next, merged(n.t + 1)), g, false);
      if (!inserted) {
        if (it->second.second || g >= it->second.first) return;
        it->second.first = g;
      }
      nodes.push_back({next, n.t + 1, g, index});
      open.emplace(g + h[next], -(n.t + 1), static_cast<int>(nodes.size()) - 1);
    };
    tryStep(n.vertex);
    for (const int next : q.graph->neighbours(n.vertex)) tryStep(next);
  }
  return Outcome::NoPath;
}

}  // namespace

DenseTeamResult planDenseTeam(const DenseTeamQuery& q) {
  DenseTeamResult out;
  const int n = static_cast<int>(q.starts.size());
  std::vector<std::vector<int>> h;
  for (int a = 0; a < n; ++a) h.push_back(distancesTo(*q.graph, q.goals[a]));
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return h[a][q.starts[a]] > h[b][q.starts[b]]; });
  EllipsoidReservations reserved(*q.positions, q.ellipsoid, q.separation, q.pitch);
  long expansions = 0;
  int restarts = 0;
  for (;; ++restarts) {
    reserved.clear();
    std::vector<std::vector<int>> paths(n);
    int failed = -1;
    Outcome outcome = Outcome::Found;
    for (const int a : order) {
      outcome = searchAgent(q, reserved, h[a], q.starts[a], q.goals[a], paths[a], expansions);
      if (outcome != Outcome::Found) {
        failed = a;
        break;
      }
      reserved.reserve(paths[a]);
    }
    if (failed < 0) {
      std::size_t length = 0;
      for (const auto& p : paths) length = std::max(length, p.size());
      for (auto& p : paths) p.resize(length, p.back());
      out.paths = std::move(paths);
      out.success = true;
      out.status = PlannerStatus::ExactSolution;
      break;
    }
    const bool expired = q.deadline && q.deadline->expired();
    if (outcome == Outcome::OutOfBudget || expired || restarts >= n) {
      out.status = expired                           ? expiredStatus(*q.deadline)
                   : outcome == Outcome::OutOfBudget ? PlannerStatus::LimitReached
                                                     : PlannerStatus::NoSolution;
      out.message =
          (expired                           ? std::string("time limit reached")
           : outcome == Outcome::OutOfBudget ? "the search's expansion limit reached"
                                             : "no route around the higher-priority agents") +
          " while planning agent " + std::to_string(failed) + " (" + std::to_string(restarts) +
          " reorderings)";
      break;
    }
    order.erase(std::find(order.begin(), order.end(), failed));
    order.insert(order.begin(), failed);
  }
  out.counters["expansions"] = static_cast<double>(expansions);
  out.counters["restarts"] = restarts;
  return out;
}

double closestLockStepDistance(const std::vector<std::vector<int>>& paths,
                               const std::vector<Eigen::Vector3d>& positions,
                               const SeparationEllipsoid& ellipsoid) {
  double closest = std::numeric_limits<double>::infinity();
  std::size_t length = 0;
  for (const auto& p : paths) length = std::max(length, p.size());
  const auto at = [&](const std::vector<int>& p, std::size_t t) {
    return positions[p[std::min(t, p.size() - 1)]];
  };
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t j = i + 1; j < paths.size(); ++j)
      for (std::size_t t = 0; t < std::max<std::size_t>(length, 2) - 1; ++t)
        closest = std::min(closest,
                           sweptEllipsoidDistance(ellipsoid, at(paths[i], t), at(paths[i], t + 1),
                                                  at(paths[j], t), at(paths[j], t + 1)));
  return closest;
}

}  // namespace cosim
