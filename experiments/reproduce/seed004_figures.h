#pragma once
// Figures and measures shared by the seed-004 reproductions: one multi-robot instance drawn with
// the agents' paths under several planners, and how many agents of a bottleneck instance must
// pass its door.
#include <string>
#include <utility>
#include <vector>

#include "experiments/reproduce/mapf_trial.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim::reproduce {

// Writes out_dir/NAME_map<index>.png/.svg: the instance's grid, every agent's start and goal,
// and each trial's paths (one line per planner and agent, labelled "planner, robot k").
// Returns the file base.
std::string drawMapfInstance(const std::string& out_dir, const std::string& name, int index,
                             const std::string& title, const MapfInstance& instance,
                             const std::vector<std::pair<std::string, const MapfTrial*>>& trials);

// The share of agents whose start and goal lie on opposite sides of a bottleneck map's dividing
// wall (column width / 2): those that must pass the door.
double doorCrossingShare(const MapfInstance& instance);

// Failures of a set of trials by cause: "time limit", "step limit" (not all arrived in the
// allowed steps), "no route in window", "other"; "cause n, cause n" or "none".
std::string failureCauses(const std::vector<MapfTrial>& trials);

}  // namespace cosim::reproduce
