#pragma once
// What `cosim run` and `cosim plan` check before they create their output folder or print a
// progress line: the scenario loads, and every planner it names exists and takes the parameters
// given. A bad input then leaves nothing behind, not even an empty folder, and a planner error
// names the line of `planner.name` in the scenario file (or the --set assignment that gave it).
#include <string>
#include <vector>

#include "sim/scenario.h"

namespace cosim {

enum class PlannerUse {
  Run,          // as `cosim run` builds them (team planners and navigators for ground robots)
  FirstVehicle  // as `cosim plan` does: one single-agent plan for the first vehicle
};

// Builds every planner the run of `scenario` would build (the team planner, navigator or
// single-agent planner of the robots, the quadrotors' planner), reading the parameters the run
// reads, so that an unknown planner or parameter is found without running: sweeps check each
// job with it before starting any. Throws InputError as the run would.
void checkRunPlanners(const Scenario& scenario);

// loadScenario, then the planners of `use` built once and thrown away. Throws InputError.
Scenario loadCheckedScenario(const std::string& path, const std::vector<std::string>& overrides,
                             PlannerUse use);

// loadCheckedScenario for a first-vehicle plan (`cosim plan`, Python's cosim.plan) with `planner`,
// when not empty, as planner.name: an error about that planner names the place `--planner NAME`,
// where the user gave it, not the --set assignment it becomes.
Scenario loadScenarioForPlan(const std::string& path, std::vector<std::string> overrides,
                             const std::string& planner);

// "line 7, key planner.name" for the dotted `key` of a scenario file, or the --set assignment
// that gave it ("--set planner.name=cbs, key planner.name"), or "key KEY" if neither.
std::string scenarioKeyPlace(const std::string& path, const std::vector<std::string>& overrides,
                             const std::string& key);

}  // namespace cosim
