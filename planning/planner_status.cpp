#include "planning/planner_status.h"

namespace cosim {

std::string toString(PlannerStatus status) {
  switch (status) {
    case PlannerStatus::Unknown:
      return "unknown";
    case PlannerStatus::ExactSolution:
      return "exact_solution";
    case PlannerStatus::ApproximateSolution:
      return "approximate_solution";
    case PlannerStatus::Timeout:
      return "timeout";
    case PlannerStatus::Stopped:
      return "stopped";
    case PlannerStatus::LimitReached:
      return "limit_reached";
    case PlannerStatus::NoSolution:
      return "no_solution";
    case PlannerStatus::InvalidStart:
      return "invalid_start";
    case PlannerStatus::InvalidGoal:
      return "invalid_goal";
    case PlannerStatus::InvalidProblem:
      return "invalid_problem";
    case PlannerStatus::InvalidSolution:
      return "invalid_solution";
  }
  return "unknown";
}

}  // namespace cosim
