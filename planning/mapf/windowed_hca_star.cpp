#include "planning/mapf/windowed_hca_star.h"

#include <algorithm>
#include <memory>

#include "planning/mapf/mapf_search_context.h"
#include "planning/mapf/reservation_table.h"
#include "planning/mapf/space_time_astar.h"

namespace cosim {

namespace {

// One WHCA* run: where the agents are, what they have executed, their priorities and counters.
class WindowedRun {
 public:
  WindowedRun(MapfSearchContext& context, const WindowedHcaStarOptions& options,
              std::vector<std::unique_ptr<GoalDistance>> distance)
      : context_(context),
        options_(options),
        grid_(context.grid()),
        n_(context.agentCount()),
        dynamic_(options.priorities == PriorityPolicy::kDynamic),
        distance_(std::move(distance)),
        position_(n_),
        goal_(n_),
        priority_(n_, 0),
        executed_(n_),
        search_(grid_),
        table_(grid_) {
    for (int a = 0; a < n_; ++a) {
      position_[a] = context.start(a);
      goal_[a] = context.goal(a);
      executed_[a].push_back(position_[a]);
    }
  }

  // The first agent whose goal is unreachable, or -1.
  int unreachableAgent() const {
    for (int a = 0; a < n_; ++a)
      if (distance_[a]->distance(position_[a]) >= GoalDistance::kUnreachable) return a;
    return -1;
  }

  // Rounds of planning `window` steps ahead and executing part of it, until every agent is on
  // its goal (success) or the run gives up: the message says why, `gave_up` how.
  void run(MapfResult& result, PlannerStatus& gave_up) {
    const int max_steps = options_.max_steps > 0 ? options_.max_steps : grid_.cellCount();
    int t0 = 0;
    while (result.message.empty()) {
      if (position_ == goal_) {
        result.success = true;
        break;
      }
      if (t0 >= max_steps) {
        result.message = "not all agents arrived within " + std::to_string(max_steps) + " steps";
        gave_up = PlannerStatus::ApproximateSolution;
        break;
      }
      if (context_.deadline().expired()) {
        result.message = "time limit reached";
        break;
      }
      ++rounds_;
      // Seed 004 §4.5: "extend the time window to the max of the priorities", bounded here by
      // the thesis's rule of thumb w = number of agents (§3.5) so that it cannot grow without end.
      const int max_priority = *std::max_element(priority_.begin(), priority_.end());
      const int window = dynamic_ ? std::min(std::max(options_.window, max_priority),
                                             std::max(options_.window, n_))
                                  : options_.window;
      std::vector<std::vector<int>> plans(n_);
      result.message = planWindow(t0, window, plans);
      if (!result.message.empty()) break;
      const int steps = options_.replan_every > 0 ? std::min(options_.replan_every, window)
                                                  : std::max(1, window / 2);
      execute(plans, steps);
      t0 += steps;
    }
  }

  void storeResult(MapfResult& result) const {
    for (int a = 0; a < n_; ++a) {
      MapfPath path = grid_.toCells(executed_[a]);
      if (result.success) trimWaitsAtEnd(path);
      result.paths.push_back(std::move(path));
    }
    result.counters["expansions"] = static_cast<double>(expansions_);
    result.counters["rounds"] = static_cast<double>(rounds_);
    result.counters["priority_retries"] = static_cast<double>(retries_);
  }

 private:
  // Plans every agent `window` steps from t0 in priority order into `plans`; with dynamic
  // priorities an agent without a route is raised and all are planned again. Returns why no
  // plan was found, or empty.
  std::string planWindow(int t0, int window, std::vector<std::vector<int>>& plans) {
    for (int attempt = 0;; ++attempt) {
      table_.clear();
      int failed = -1;
      for (const int a : planningOrder(priority_)) {
        SpaceTimeRequest request;
        request.start = position_[a];
        request.goal = goal_[a];
        request.start_time = t0;
        request.window = window;
        request.constraints = &table_;
        request.heuristic = distance_[a].get();
        request.max_expansions = options_.max_expansions;
        request.deadline = &context_.deadline();
        const SpaceTimePlan plan = search_.plan(request);
        expansions_ += plan.expansions;
        if (!plan.found) {
          failed = a;
          break;
        }
        table_.reservePath(plan.cells, t0, /*park=*/false);
        plans[a] = plan.cells;
      }
      if (failed < 0) return {};
      if (context_.deadline().expired()) return "time limit reached";
      if (!dynamic_ || attempt >= n_)
        return "agent " + std::to_string(failed) +
               " found no route in the window at t=" + std::to_string(t0);
      // Seed 004 §4.5: the agent without a route gets the highest priority; plan again.
      ++retries_;
      priority_[failed] = *std::max_element(priority_.begin(), priority_.end()) + 1;
    }
  }

  // Executes the first `steps` steps of every agent's plan.
  void execute(const std::vector<std::vector<int>>& plans, int steps) {
    for (int a = 0; a < n_; ++a) {
      const int before = distance_[a]->distance(position_[a]);
      for (int i = 1; i <= steps; ++i) executed_[a].push_back(plans[a][i]);
      position_[a] = plans[a][steps];
      // Seed 004 §4.5: "raise the priority in each step if no route was found, and retry in the
      // next step": an agent that got no closer to its goal is planned earlier next time.
      if (dynamic_ && position_[a] != goal_[a] && distance_[a]->distance(position_[a]) >= before)
        ++priority_[a];
    }
  }

  MapfSearchContext& context_;
  const WindowedHcaStarOptions& options_;
  const MapfGrid& grid_;
  const int n_;
  const bool dynamic_;
  std::vector<std::unique_ptr<GoalDistance>> distance_;
  std::vector<int> position_, goal_, priority_;
  std::vector<std::vector<int>> executed_;
  SpaceTimeAStar search_;
  ReservationTable table_;
  long expansions_ = 0, rounds_ = 0, retries_ = 0;
};

}  // namespace

MapfResult WindowedHcaStar::solve(const MapfQuery& query, const StopToken& stop) {
  MapfSearchContext context(query, stop);
  auto distance = context.goalDistances(MapfSearchContext::Heuristic::kTrueDistance);
  if (static_cast<int>(distance.size()) < context.agentCount()) return context.timeUp();
  WindowedRun run(context, options_, std::move(distance));
  // (a distance search cut short by the deadline finds nothing either)
  if (const int a = run.unreachableAgent(); a >= 0) return context.unreachable(a);
  MapfResult result;
  PlannerStatus gave_up = PlannerStatus::NoSolution;  // why the run ended without a solution
  run.run(result, gave_up);
  result.status = searchStatus(result.success, context.deadline(), gave_up);
  run.storeResult(result);
  return context.finish(std::move(result));
}

}  // namespace cosim
