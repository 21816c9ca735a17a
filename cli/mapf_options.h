#pragma once
// `cosim mapf`'s options as given on the command line, and how their text is read: agent counts
// (N or START:STOP:STEP), --block cells, planner lists.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim::cli {

struct MapfArgs {
  std::string map, planner, out, agents;
  std::vector<std::string> scens;
  int window = 0, connectivity = 4;
  bool keep_going = false;
  double time_limit = 60.0;
  bool execute = false, video = false;
  std::string robot = "omni_base";
  double cell = 0.0, max_time = 300.0, video_speed = 4.0;
  std::uint64_t seed = 1;
  std::vector<std::string> sets, blocks;

  // The planner parameters: every --set, and --window W as window=W.
  std::vector<std::string> plannerSets() const;
};

// "N" or "START:STOP:STEP" (START, START + STEP, ... up to STOP). Throws InputError (place
// --agents) for anything else, counts below 1, STOP below START or more than 10000 counts.
std::vector<int> parseAgentCounts(const std::string& text);

// "X,Y" (column, row) of a --block cell; InputError otherwise.
Cell parseBlockCell(const std::string& text);

// "a,b,c" -> {"a", "b", "c"}; empty names are bad input.
std::vector<std::string> splitPlannerList(const std::string& text);

// --agents: N within the planners' limit, or a range (checked by parseAgentCounts).
CLI::Validator agentCountOrRange();

}  // namespace cosim::cli
