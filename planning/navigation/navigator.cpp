#include "planning/navigation/navigator.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "core/stop_token.h"

namespace cosim {

NavigationRun runNavigation(Navigator& navigator, const NavigationWorld& world, const Cell& start,
                            const Cell& goal, const NavigationLimits& limits, std::uint64_t seed) {
  const StopToken deadline =
      limits.stop ? StopToken(limits.time_limit_s, *limits.stop) : StopToken(limits.time_limit_s);
  const OccupancyGrid& grid = world.grid();
  NavigationRun run;
  if (grid.blocked(start.x, start.y) || grid.blocked(goal.x, goal.y)) {
    run.message = grid.blocked(start.x, start.y) ? "start cell is blocked" : "goal cell is blocked";
    run.status = grid.blocked(start.x, start.y) ? PlannerStatus::InvalidStart
                                                : PlannerStatus::InvalidGoal;
    return run;
  }
  navigator.reset(world, start, goal, seed);
  const long long max_decisions = limits.max_decisions > 0
                                      ? limits.max_decisions
                                      : 20LL * static_cast<long long>(grid.cellCount());
  Cell at{start.x, start.y, 0};
  double t = 0.0, plan_ms_sum = 0.0;
  long long decisions = 0;
  run.cells.push_back(at);
  run.times.push_back(0.0);
  while (!(at.x == goal.x && at.y == goal.y)) {
    if (decisions >= max_decisions || deadline.expired()) {
      run.message = deadline.expired() ? "time limit" : "decision limit reached";
      run.status = deadline.expired() ? expiredStatus(deadline) : PlannerStatus::LimitReached;
      break;
    }
    NavigationDecision d = navigator.decide(at, t);
    ++decisions;
    run.replans += d.replans;
    plan_ms_sum += d.plan_ms;
    run.max_plan_ms = std::max(run.max_plan_ms, d.plan_ms);
    if (d.give_up) {
      run.message = d.note.empty() ? "navigator gave up" : d.note;
      run.status = PlannerStatus::NoSolution;
      break;
    }
    const int dx = d.next.x - at.x, dy = d.next.y - at.y;
    const bool wait = dx == 0 && dy == 0;
    if (std::abs(dx) > 1 || std::abs(dy) > 1 || grid.blocked(d.next.x, d.next.y, 0)) {
      run.status = PlannerStatus::NoSolution;  // a navigator's fault, reported as no path
      run.message =
          "illegal move to (" + std::to_string(d.next.x) + ", " + std::to_string(d.next.y) + ")";
      break;
    }
    const double duration = wait ? 1.0 : std::sqrt(static_cast<double>(dx * dx + dy * dy));
    const Cell next{d.next.x, d.next.y, 0};
    if (world.robotHitsObstacle(at, next, t, duration)) ++run.collisions;
    t += duration;
    if (wait) {
      ++run.waits;
    } else {
      ++run.steps;
      run.length += duration;
      at = next;
      run.cells.push_back(at);
      run.times.push_back(t);
    }
    if (limits.record_decisions) run.decisions.push_back(std::move(d));
  }
  run.reached = at.x == goal.x && at.y == goal.y;
  if (run.reached) run.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
  run.travel_time = t;
  run.mean_plan_ms = decisions > 0 ? plan_ms_sum / static_cast<double>(decisions) : 0.0;
  return run;
}

}  // namespace cosim
