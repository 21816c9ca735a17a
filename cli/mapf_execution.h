#pragma once
// `cosim mapf --execute`: a MAPF instance on a MovingAI map, driven by ground robots in MuJoCo.
// The instance becomes an ordinary scenario (world.grid_map with the map, one robot per agent at
// its start cell's centre, the same planner and parameters), written next to the results so the
// execution can be re-run with `cosim run` (which plans again: same planner, parameters and seed
// on the map's own cells), and executed by the ground pipeline, which drives the plan the command
// printed and wrote (RunRequest::given_team_plan) instead of searching a second time.
#include <cstdint>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim::cli {

struct MapfExecutionSetup {
  std::string map_path;             // absolute
  std::vector<Cell> extra_blocked;  // --block cells
  std::vector<Cell> starts, goals;  // the agents (x = column, y = row)
  std::string planner;
  std::vector<std::string> planner_sets;  // "key=value" planner parameters (--set, --window)
  int connectivity = 4;
  double time_limit_s = 60.0;
  std::uint64_t seed = 1;
  std::string robot = "omni_base";  // a bundled ground model or a URDF path
  double cell = 0.5;                // m
  double max_time_s = 300.0;        // simulated seconds before giving up
  double video_speed = 0.0;         // render.speed (0: the default)
};

// The scenario YAML of the execution.
std::string mapfExecutionScenarioYaml(const MapfExecutionSetup& setup);

}  // namespace cosim::cli
