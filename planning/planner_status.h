#pragma once
// How a planner's search ended, as OMPL's PlannerStatus says it: every planner result (PlanResult,
// GridPlanResult, MapfResult) carries one beside its free-text message, so that callers branch on
// a value, not on wording. A stop request (SIGINT/SIGTERM, core/stop_request.h, or a caller's own
// flag) ends a search as Stopped, never as Timeout: the command line then treats the result as
// interrupted and writes nothing that looks finished.
#include <string>

#include "core/stop_token.h"

namespace cosim {

enum class PlannerStatus {
  Unknown,              // not set: every planner sets one (tests/planning/planner_status_test)
  ExactSolution,        // a path (all paths) from start to goal
  ApproximateSolution,  // paths that are not a solution: agents short of their goals (a
                        // step-by-step team planner out of steps) or in conflict (the
                        // uncoordinated baseline)
  Timeout,              // the time limit ran out first
  Stopped,              // a stop request ended the search
  LimitReached,         // a node, expansion, step, iteration, repair or memory budget ran out
  NoSolution,           // the search is complete and there is no path (or it gave up without one)
  InvalidStart,         // the start is blocked, off the map or unusable
  InvalidGoal,          // the goal is blocked, off the map or unusable
  InvalidProblem,       // the query itself cannot be searched (no grid, start and goal on
                        // different layers of a 2D planner)
  InvalidSolution,      // the planner claimed a solution that the independent check rejected
                        // (set by the checker, e.g. `cosim mapf`, never by a planner)
};

// "exact_solution", "timeout", "stopped", ...: the "status" value of plan.json and mapf.json.
std::string toString(PlannerStatus status);

// A search cut short by its StopToken: Stopped when a stop was requested, Timeout otherwise.
inline PlannerStatus expiredStatus(const StopToken& token) {
  return token.stopRequested() ? PlannerStatus::Stopped : PlannerStatus::Timeout;
}

// How a search that has returned ended: Stopped when a stop was requested (even if it found a
// path first: an interrupted command keeps nothing), else ExactSolution when it found one, else
// Timeout when its time ran out, else `otherwise` (why it gave up: NoSolution, LimitReached).
inline PlannerStatus searchStatus(bool found, const StopToken& token, PlannerStatus otherwise) {
  if (token.stopRequested()) return PlannerStatus::Stopped;
  if (found) return PlannerStatus::ExactSolution;
  return token.expired() ? PlannerStatus::Timeout : otherwise;
}

}  // namespace cosim
