#pragma once
// The moments of a run worth a marker on a replay's timeline: the closest approach of a vehicle
// to an obstacle, the closest approach of two vehicles, the largest tracking error, and every
// collision onset.
#include <string>
#include <vector>

#include "planning/world/world.h"
#include "sim/run_log.h"

namespace cosim {

struct RunMoment {
  std::string kind;    // "closest_approach", "closest_pair", "worst_error", "collision"
  double t = 0.0;      // s
  int vehicle = -1;    // index into log.vehicles
  int other = -1;      // closest_pair: the second vehicle
  double value = 0.0;  // m: clearance, separation (centre distance less both radii), or error
  std::string label;   // for a person: "closest approach: 0.41 m (uav1 at 12.3 s)"
};

// Work a search may do (vehicle samples times obstacles, or samples times vehicle pairs): past it
// the moment is left out rather than making a 1000-robot run wait.
constexpr double kMomentSearchBudget = 3e7;

// The moments, in time order. The searches look at every `stride`-th sample of each vehicle (at
// least 1); the tracking error is |position - reference|.
std::vector<RunMoment> runMoments(const RunLog& log, const World& world, int stride);

}  // namespace cosim
