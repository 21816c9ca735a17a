#pragma once
// What planning came to for a group of a run's vehicles (its ground robots, or its quadrotors):
// whether they can be driven, and the planner's figures that metrics.json reports.
#include <map>
#include <string>
#include <vector>

#include "run/scenario_planning.h"

namespace cosim {

enum class PlanStatus {
  Ready,        // every vehicle has a plan it can follow
  Conflicting,  // the robots' team plan has conflicts: driven anyway (the physics shows what
                // they cost), and the run fails
  NoPath,       // a planner found no path (or no team plan)
  NoTrajectory  // a quadrotor's path could not be turned into a feasible trajectory
};

// Whether vehicles with plans of this status are simulated.
inline bool drivable(PlanStatus status) {
  return status == PlanStatus::Ready || status == PlanStatus::Conflicting;
}

// The summary of plans made one vehicle at a time (times, counters summed; the largest inflation).
PlanSummary summarizeSeparatePlans(const std::vector<VehiclePlan>& plans);

}  // namespace cosim
