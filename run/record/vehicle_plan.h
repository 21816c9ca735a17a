#pragma once
// What planning made of a run's vehicles, as the run's record keeps it (run/record/run_record.h):
// each vehicle's plan, and the planner's figures of a group of them.
#include <map>
#include <string>
#include <vector>

#include "planning/path.h"
#include "planning/planner_status.h"

namespace cosim {

struct VehiclePlan {
  bool success = false;
  Path path;
  double time_ms = 0.0;
  std::map<std::string, double> counters;     // summed over segments
  std::map<std::string, std::string> params;  // the planner's parameters in force
  std::string message;
  PlannerStatus status = PlannerStatus::Unknown;  // the failing segment's, else ExactSolution
  double inflation = 0.0;                         // vehicle radius + margin the planner kept clear
  std::map<std::string, double> trajectory_counters;  // from the minimum-snap fit, if any
  // The file's parameters of other planners, set aside because an override chose this one
  // (run/scenario_planning.h, plannerParameters).
  std::vector<std::string> set_aside_params;
  // Indices in `path` of the vehicle's waypoints (the points it was asked to visit, the goal
  // last): a trajectory through the path must not cut past them.
  std::vector<std::size_t> via_indices;
  // When the vehicle is due at each point of `path` (s): a ground robot's timed plan. Empty for
  // a path without times (a quadrotor's reference is timed by its trajectory).
  std::vector<double> point_times;
};

// The planner's figures of a group, as metrics.json reports them at the top level.
struct PlanSummary {
  double time_ms = 0.0;                       // planning time of the whole group
  std::map<std::string, double> counters;     // a team plan's, or summed over separate plans
  std::map<std::string, std::string> params;  // the planner's parameters in force
  double inflation = 0.0;                     // the largest radius + margin kept clear
};

}  // namespace cosim
