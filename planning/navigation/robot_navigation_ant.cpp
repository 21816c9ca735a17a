#include "planning/navigation/robot_navigation_ant.h"

#include <cmath>
#include <limits>

#include "core/stop_token.h"
#include "planning/grid/dijkstra.h"

namespace cosim {

namespace {
bool sameCell(const Cell& a, const Cell& b) {
  return a.x == b.x && a.y == b.y;
}
double distance(const Cell& a, const Cell& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}
}  // namespace

void RobotNavigationAnt::reset(const NavigationWorld& world, const Cell& start, const Cell& goal,
                               std::uint64_t seed) {
  world_ = &world;
  goal_ = {goal.x, goal.y, 0};
  seed_ = seed;
  decisions_ = 0;
  waits_in_a_row_ = 0;
  has_previous_ = false;
  visited_.assign(world.grid().cellCount(), 0);
  visited_[world.grid().index(start.x, start.y)] = 1;
  temporary_.clear();
  lifted_.clear();
}

bool RobotNavigationAnt::wasLifted(const Cell& c) const {
  for (const Cell& b : lifted_)
    if (sameCell(b, c)) return true;
  return false;
}

bool RobotNavigationAnt::liftNewestTemporary(const Cell& at) {
  // §4.2 b: only the temporary obstacles in the field of view count.
  auto newest = [&](bool skip_lifted) {
    for (auto it = temporary_.end(); it != temporary_.begin();) {
      --it;
      if (NavigationWorld::inView(at, *it, p_.sight) && !(skip_lifted && wasLifted(*it))) return it;
    }
    return temporary_.end();
  };
  auto it = newest(true);
  if (it == temporary_.end()) it = newest(false);  // all in view were lifted before
  if (it == temporary_.end()) return false;
  if (!wasLifted(*it)) lifted_.push_back(*it);
  temporary_.erase(it);
  return true;
}

bool RobotNavigationAnt::temporarilyBlocked(const Cell& c) const {
  for (const Cell& b : temporary_)
    if (sameCell(b, c)) return true;
  return false;
}

RobotNavigationAnt::Window RobotNavigationAnt::buildWindow(const Cell& at) const {
  const OccupancyGrid& truth = world_->grid();
  const int r = p_.sight;
  const int x0 = std::max(0, at.x - r - 1), x1 = std::min(truth.nx() - 1, at.x + r + 1);
  const int y0 = std::max(0, at.y - r - 1), y1 = std::min(truth.ny() - 1, at.y + r + 1);
  Window w{x0, y0, OccupancyGrid(x1 - x0 + 1, y1 - y0 + 1)};
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Cell c{x, y, 0};
      // In view: what the sensor shows. The ring just outside: assumed free (seed §2.4).
      const bool seen_blocked = NavigationWorld::inView(at, c, r) && truth.blocked(x, y);
      w.grid.setBlocked(x - x0, y - y0, 0, seen_blocked);
    }
  for (const Cell& b : temporary_)
    if (b.x >= x0 && b.x <= x1 && b.y >= y0 && b.y <= y1 && !sameCell(b, at) && !sameCell(b, goal_))
      w.grid.setBlocked(b.x - x0, b.y - y0, 0, true);
  return w;
}

bool RobotNavigationAnt::localGoal(const Window& w, const Cell& at, Cell& goal) const {
  // Cells of the window the robot can reach (flood fill over what it sees, the ring assumed
  // free, temporary obstacles blocked). Deviation from the seed, which took the nearest ring
  // cell even when its view showed that cell walled off (the robot then had no path and waited
  // until it gave up).
  const OccupancyGrid& g = w.grid;
  std::vector<unsigned char> reach(g.cellCount(), 0);
  std::vector<Cell> stack{{at.x - w.x0, at.y - w.y0, 0}};
  reach[g.index(stack.back())] = 1;
  const auto steps = gridSteps(GridMoves{8, !p_.conditional_diagonal}, false);
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    for (const GridStep& s : steps) {
      const Cell n{c.x + s.dx, c.y + s.dy, 0};
      if (!gridStepAllowed(g, c, s, !p_.conditional_diagonal) || reach[g.index(n)]) continue;
      reach[g.index(n)] = 1;
      stack.push_back(n);
    }
  }
  auto reachable = [&](const Cell& c) {
    const int lx = c.x - w.x0, ly = c.y - w.y0;
    return g.inside(lx, ly) && reach[g.index(lx, ly)] != 0;
  };
  const int r = p_.sight;
  if (NavigationWorld::inView(at, goal_, r) && reachable(goal_)) {
    goal = goal_;
    return true;
  }
  // The reachable cell of the enlarged ring nearest to the global goal.
  double best = std::numeric_limits<double>::infinity();
  for (int y = at.y - r - 1; y <= at.y + r + 1; ++y)
    for (int x = at.x - r - 1; x <= at.x + r + 1; ++x) {
      const Cell c{x, y, 0};
      if (std::max(std::abs(x - at.x), std::abs(y - at.y)) != r + 1 || !reachable(c)) continue;
      const double d = distance(c, goal_);
      if (d < best) {
        best = d;
        goal = c;
      }
    }
  return best < std::numeric_limits<double>::infinity();
}

bool RobotNavigationAnt::plan(const Window& w, const Cell& at, const Cell& goal, double s_max_scale,
                              std::vector<Cell>& path, double time_limit_s) {
  GridQuery q;
  q.grid = &w.grid;
  q.start = {at.x - w.x0, at.y - w.y0, 0};
  q.goal = {goal.x - w.x0, goal.y - w.y0, 0};
  q.time_limit_s = time_limit_s;
  q.seed = seed_ + 7919ULL * static_cast<std::uint64_t>(decisions_) +
           static_cast<std::uint64_t>(s_max_scale * 10);
  if (w.grid.blocked(q.goal)) return false;
  GridPlanResult r;
  if (p_.wave_front) {
    Dijkstra wave(GridMoves{8, !p_.conditional_diagonal});
    r = wave.solveGrid(q, StopToken::untimed());
  } else {
    MsacParams mp = p_.msac;
    mp.conditional_diagonal = p_.conditional_diagonal;
    const int n = std::max(w.grid.nx(), w.grid.ny());
    mp.s_max = std::max(1, static_cast<int>(s_max_scale * (n * n / 2)));
    r = Msac(mp).solveGrid(q, StopToken::untimed());
  }
  if (!r.success || r.cells.size() < 2) return false;
  path.clear();
  for (const Cell& c : r.cells) path.push_back({c.x + w.x0, c.y + w.y0, 0});
  return true;
}

NavigationDecision RobotNavigationAnt::evade(const Cell& at, const Cell& goal,
                                             const CollisionPredictor& predictor,
                                             NavigationDecision d) const {
  if (predictor.stepSafe(at, at)) return d;  // waiting is safe
  if (evasiveStep(*world_, predictor, at, goal, p_.conditional_diagonal, temporary_, d.next))
    d.note = "evade: waiting would collide";
  return d;
}

NavigationDecision RobotNavigationAnt::decide(const Cell& at_in, double t) {
  const StopToken clock(1e9);
  const Cell at{at_in.x, at_in.y, 0};
  ++decisions_;
  visited_[world_->grid().index(at.x, at.y)] = 1;
  NavigationDecision d;
  d.next = at;
  auto finish = [&](NavigationDecision& out) {
    out.plan_ms = clock.elapsedMs();
    return out;
  };
  const double plan_limit = 2.0;
  Window w = buildWindow(at);
  const CollisionPredictor predictor(*world_, p_.prediction, at, p_.sight, t);
  Cell local{};
  std::vector<Cell> path;
  bool found = localGoal(w, at, local) && plan(w, at, local, 1.0, path, plan_limit);
  d.replans = 1;
  if (!found) {
    // §4.2.2: lift the newest anti-oscillation obstacle and search with S_max x 1.5.
    if (liftNewestTemporary(at)) w = buildWindow(at);
    found = localGoal(w, at, local) && plan(w, at, local, 1.5, path, plan_limit);
    ++d.replans;
  }
  if (!found) {
    if (++waits_in_a_row_ > p_.max_waits) {
      d.give_up = true;
      d.note =
          "no path found in the given time (" + std::to_string(p_.max_waits) + " waits in a row)";
      return finish(d);
    }
    d.note = "wait: no path in view";
    d = evade(at, goal_, predictor, d);
    has_previous_ = false;
    return finish(d);
  }
  waits_in_a_row_ = 0;
  if (predictor.anyVisible()) {
    // §4.2.1: block every predicted collision point and re-plan until the plan is clear.
    bool clear = false;
    for (int r = 0;; ++r) {
      std::vector<Cell> points = predictor.collisionPoints(path);
      if (!predictor.stepSafe(path[0], path[1])) points.push_back(path[1]);
      if (points.empty()) {
        clear = true;
        break;
      }
      if (r >= p_.max_replans) break;
      for (const Cell& c : points) {
        const int lx = c.x - w.x0, ly = c.y - w.y0;
        if (w.grid.inside(lx, ly)) w.grid.setBlocked(lx, ly, 0, true);
      }
      ++d.replans;
      if (!plan(w, at, local, 1.0, path, plan_limit)) break;
    }
    if (!clear) {
      d.note = "wait: predicted collision";
      d = evade(at, local, predictor, d);
      has_previous_ = false;
      return finish(d);
    }
  }
  d.next = path[1];
  d.planned = path;
  // Anti-oscillation: the cell the robot moves back out of becomes a temporary obstacle.
  const bool back =
      has_previous_ && (p_.oscillation_any ? visited_[world_->grid().index(d.next.x, d.next.y)] != 0
                                           : sameCell(d.next, previous_));
  if (back && !temporarilyBlocked(at)) temporary_.push_back(at);
  previous_ = at;
  has_previous_ = true;
  return finish(d);
}

}  // namespace cosim
