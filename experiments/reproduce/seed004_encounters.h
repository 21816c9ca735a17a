#pragma once
// What the robots did in one multi-robot run, for the seed-004 findings that are about behaviour
// rather than success: whether two robots near each other backed off at the same step (§6.1:
// the author's "retreating of both robots does not work, one always waits"), and whether a
// failed run went round in circles (the same joint positions again and again: a livelock).
#include "experiments/reproduce/mapf_trial.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim::reproduce {

// Steps at which two robots within two cells of each other (Chebyshev) both moved to a cell
// farther from their own goal (true distance on the instance's graph): a mutual retreat.
int mutualRetreatSteps(const MapfInstance& instance, const MapfTrial& trial);

// True if some joint position of all robots occurs three times or more in the run while the
// robots still move in its last `tail` steps (a cycle, not a standstill).
bool cyclesThroughJointPositions(const MapfTrial& trial, int tail = 10);

}  // namespace cosim::reproduce
