#include "planning/navigation/d_star_lite.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/stop_token.h"

namespace cosim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSqrt2 = 1.4142135623730951;
}  // namespace

void DStarLite::reset(const NavigationWorld& world, const Cell& start, const Cell& goal,
                      std::uint64_t /*seed: D* Lite is deterministic*/) {
  world_ = &world;
  nx_ = world.grid().nx();
  ny_ = world.grid().ny();
  const std::size_t n = static_cast<std::size_t>(nx_) * ny_;
  g_.assign(n, kInf);
  rhs_.assign(n, kInf);
  known_blocked_.assign(n, 0);  // the freespace assumption
  queued_.assign(n, 0);
  queued_key_.assign(n, Key{kInf, kInf});
  open_ = {};
  km_ = 0.0;
  expansions_ = 0;
  planned_once_ = false;
  start_ = last_ = start.y * nx_ + start.x;
  goal_ = goal.y * nx_ + goal.x;
  rhs_[goal_] = 0.0;
  push(goal_, Key{h(start_, goal_), 0.0});
}

double DStarLite::h(int a, int b) const {
  const double dx = std::abs(a % nx_ - b % nx_), dy = std::abs(a / nx_ - b / nx_);
  return std::max(dx, dy) + (kSqrt2 - 1.0) * std::min(dx, dy);
}

double DStarLite::cost(int a, int b) const {
  if (known_blocked_[a] || known_blocked_[b]) return kInf;
  const int ax = a % nx_, ay = a / nx_, bx = b % nx_, by = b / nx_;
  if (ax == bx || ay == by) return 1.0;
  if (p_.conditional_diagonal && (known_blocked_[ay * nx_ + bx] || known_blocked_[by * nx_ + ax]))
    return kInf;
  return kSqrt2;
}

int DStarLite::neighbourCells(int u, int* out) const {
  const int ux = u % nx_, uy = u / nx_;
  int n = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int x = ux + dx, y = uy + dy;
      if ((dx || dy) && x >= 0 && y >= 0 && x < nx_ && y < ny_) out[n++] = y * nx_ + x;
    }
  return n;
}

DStarLite::Key DStarLite::calculateKey(int s) const {
  const double m = std::min(g_[s], rhs_[s]);
  return Key{m + h(start_, s) + km_, m};
}

void DStarLite::push(int u, const Key& k) {
  queued_[u] = 1;
  queued_key_[u] = k;
  open_.push(Entry{k, u});
}

void DStarLite::updateVertex(int u) {
  if (u != goal_) {
    int nb[8];
    const int n = neighbourCells(u, nb);
    double best = kInf;
    for (int i = 0; i < n; ++i) best = std::min(best, cost(u, nb[i]) + g_[nb[i]]);
    rhs_[u] = best;
  }
  queued_[u] = 0;  // lazy removal: stale heap entries are skipped when they surface
  if (g_[u] != rhs_[u]) push(u, calculateKey(u));
}

bool DStarLite::computeShortestPath(double time_limit_s) {
  const StopToken deadline(time_limit_s);
  int nb[8];
  while (true) {
    while (!open_.empty() &&
           (!queued_[open_.top().cell] || !(open_.top().key == queued_key_[open_.top().cell])))
      open_.pop();
    const Key top = open_.empty() ? Key{kInf, kInf} : open_.top().key;
    if (!(top < calculateKey(start_)) && rhs_[start_] == g_[start_]) return true;
    if (open_.empty()) return true;  // nothing left to repair: start is unreachable
    if ((++expansions_ & 1023) == 0 && deadline.expired()) return false;
    const int u = open_.top().cell;
    open_.pop();
    queued_[u] = 0;
    const Key fresh = calculateKey(u);
    if (top < fresh) {
      push(u, fresh);
    } else if (g_[u] > rhs_[u]) {
      g_[u] = rhs_[u];
      const int n = neighbourCells(u, nb);
      for (int i = 0; i < n; ++i) updateVertex(nb[i]);
    } else {
      g_[u] = kInf;
      updateVertex(u);
      const int n = neighbourCells(u, nb);
      for (int i = 0; i < n; ++i) updateVertex(nb[i]);
    }
  }
}

int DStarLite::bestSuccessor(int u) const {
  int nb[8];
  const int n = neighbourCells(u, nb);
  int best = -1;
  double best_cost = kInf;
  for (int i = 0; i < n; ++i) {
    const double c = cost(u, nb[i]) + g_[nb[i]];
    if (c < best_cost) {
      best_cost = c;
      best = nb[i];
    }
  }
  return best;
}

std::vector<Cell> DStarLite::extractPlan(int from, int max_steps) const {
  std::vector<Cell> plan{{from % nx_, from / nx_, 0}};
  for (int u = from, k = 0; u != goal_ && k < max_steps; ++k) {
    u = bestSuccessor(u);
    if (u < 0) break;
    plan.push_back({u % nx_, u / nx_, 0});
  }
  return plan;
}

NavigationDecision DStarLite::decide(const Cell& at, double t) {
  const StopToken clock(1e9);
  NavigationDecision d;
  d.next = {at.x, at.y, 0};
  start_ = at.y * nx_ + at.x;
  // Sense the field of view; every cell that is not as assumed changes its edges.
  const OccupancyGrid& truth = world_->grid();
  std::vector<int> changed;
  for (int y = std::max(0, at.y - p_.sight); y <= std::min(ny_ - 1, at.y + p_.sight); ++y)
    for (int x = std::max(0, at.x - p_.sight); x <= std::min(nx_ - 1, at.x + p_.sight); ++x) {
      const int c = y * nx_ + x;
      const unsigned char b = truth.blocked(x, y) ? 1 : 0;
      if (b != known_blocked_[c]) {
        known_blocked_[c] = b;
        changed.push_back(c);
      }
    }
  if (!changed.empty()) {
    km_ += h(last_, start_);
    last_ = start_;
    int nb[8];
    for (int c : changed) {
      updateVertex(c);
      const int n = neighbourCells(c, nb);
      for (int i = 0; i < n; ++i) updateVertex(nb[i]);
    }
  }
  const bool complete = computeShortestPath(10.0);
  d.replans = changed.empty() && planned_once_ ? 0 : 1;
  planned_once_ = true;
  if (!complete || g_[start_] == kInf) {
    d.give_up = true;
    d.note = complete ? "goal unreachable on the known map" : "time limit in D* Lite";
    d.plan_ms = clock.elapsedMs();
    return d;
  }
  d.planned = extractPlan(start_, 4 * p_.sight + 4);
  const CollisionPredictor predictor(*world_, p_.prediction, d.next, p_.sight, t);
  bool go = d.planned.size() >= 2;
  if (go && predictor.anyVisible()) {
    const std::vector<Cell> points = predictor.collisionPoints(d.planned);
    for (const Cell& c : points) go = go && !(c.x == d.planned[1].x && c.y == d.planned[1].y);
    go = go && predictor.stepSafe(d.planned[0], d.planned[1]);
  }
  if (go) {
    d.next = d.planned[1];
  } else {
    d.note = "wait: predicted collision";
    if (!predictor.stepSafe(d.next, d.next) &&
        evasiveStep(*world_, predictor, d.next, d.planned.back(), p_.conditional_diagonal, {},
                    d.next))
      d.note = "evade: waiting would collide";
  }
  d.plan_ms = clock.elapsedMs();
  return d;
}

}  // namespace cosim
